// Everything a driver needs: atomic CSV, claims, --out and progress.
#pragma once
#include "repro/common/claims.hpp"
#include "repro/common/cli.hpp"
#include "repro/common/csv.hpp"
