// Catch2 main of the ctest binary property_tests: properties ([property],
// case count and seed from RC_PARAMS, set by ctest) and regressions
// ([regression], saved counterexamples, no randomness).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
