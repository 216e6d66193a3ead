// SPDX-License-Identifier: Apache-2.0
// Catch2 main for every scw test executable.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
