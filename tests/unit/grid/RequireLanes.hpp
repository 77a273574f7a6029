// REQUIRE_LANES(): a test of the AVX2 + FMA lanes (SeparableLanes) skipped where this CPU or
// this build has none, so that the scalar builds and machines still run the other tests.
#pragma once

#include "grid/SeparableLanes.hpp"

#include <gtest/gtest.h>

#define REQUIRE_LANES()                                                                                      \
    if (!::dropletFiber::SeparableLanes::available())                                                        \
    {                                                                                                        \
        GTEST_SKIP() << "this CPU has no AVX2 + FMA (or this build no AVX2 code): nothing to test";          \
    }
