// Catch2's own main(); each milestone's checkpoints register themselves (register_suite).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
