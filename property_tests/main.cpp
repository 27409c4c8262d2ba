// Catch2 main of the ctest binary property_tests: properties ([property],
// case count and seed from RC_PARAMS, set by ctest) and regressions
// ([regression], saved counterexamples, no randomness).
// Wide console: a counterexample's polygons print on one line each, ready to
// paste (Catch2 would otherwise wrap them, splitting numbers).
#define CATCH_CONFIG_CONSOLE_WIDTH 1000
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
