// Everything a driver needs: atomic CSV and column tables, claims, the shared
// main (command line, --out, progress, errors).
#pragma once
#include "repro/common/claims.hpp"
#include "repro/common/cli.hpp"
#include "repro/common/csv.hpp"
#include "repro/common/driver.hpp"
#include "repro/common/table.hpp"
