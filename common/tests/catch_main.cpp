// Catch2's own main(), shared by every test program. The checkpoint programs register their
// test cases at start-up (cp::register_suite).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
