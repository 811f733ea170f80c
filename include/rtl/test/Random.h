// Random values for tests: one shared engine, uniform values and generator callables.
//
// The engine is seeded from the system clock, or from the environment variable RTL_TEST_SEED when it is set
// (to replay a failing run); seed() reseeds it explicitly.
#pragma once

#include <chrono>
#include <cstdlib>
#include <random>
#include <type_traits>

#include "rtl/Core.h"
#include "rtl/Transformation.h"

namespace rtl::test
{
    class Random
    {
    private:
        static auto &generator()
        {
            static std::default_random_engine gen(initialSeed());
            return gen;
        }
        static std::default_random_engine::result_type initialSeed()
        {
            if (const char *s = std::getenv("RTL_TEST_SEED"))
                return static_cast<std::default_random_engine::result_type>(std::strtoul(s, nullptr, 10));
            return static_cast<std::default_random_engine::result_type>(std::chrono::system_clock::now().time_since_epoch().count());
        }

    public:
        static void seed(std::default_random_engine::result_type s) { generator().seed(s); }

        //! Uniform in [min, max] for integral T, [min, max) for floating-point T.
        template<typename T>
        static T uniformValue(T min, T max)
        {
            static_assert(std::is_integral_v<T> || std::is_floating_point_v<T>, "Random::uniformValue needs an integral or floating-point type.");
            if constexpr (std::is_same_v<T, bool>)
                return std::uniform_int_distribution<int>(min, max)(generator()) != 0;
            else if constexpr (std::is_integral_v<T> && sizeof(T) < sizeof(short))     // no distribution over char types
                return static_cast<T>(std::uniform_int_distribution<int>(min, max)(generator()));
            else if constexpr (std::is_integral_v<T>)
                return std::uniform_int_distribution<T>(min, max)(generator());
            else
                return std::uniform_real_distribution<T>(min, max)(generator());
        }

        //! A const-callable () -> T drawing uniformValue(min, max), usable as an element generator for random().
        template<typename T>
        static auto uniformCallable(T min, T max)
        {
            return [min, max]() { return uniformValue<T>(min, max); };
        }
    };
}
