// The random engine of the particle filter and the genetic algorithm (SimpleParticle, SimpleAgent, resampling,
// selection, mutation): one std::mt19937 shared by the whole program, seeded from std::random_device at first use.
// AlgorithmRandom::seed(s) makes every later run of those algorithms reproducible (same seed, same results).
#pragma once

#include <random>
#include <type_traits>

namespace rtl
{
    class AlgorithmRandom
    {
    public:
        using Engine = std::mt19937;

        static Engine &engine()
        {
            static Engine gen(std::random_device{}());
            return gen;
        }
        static void seed(Engine::result_type s) { engine().seed(s); }

        //! Uniform in [min, max] for integral T, in [min, max) for floating-point T.
        template<typename T>
        static T uniform(T min, T max)
        {
            static_assert(std::is_arithmetic_v<T> && !std::is_same_v<T, bool> && sizeof(T) >= sizeof(short),
                          "AlgorithmRandom::uniform needs an int, long or floating-point type.");
            if constexpr (std::is_integral_v<T>)
                return std::uniform_int_distribution<T>(min, max)(engine());
            else
                return std::uniform_real_distribution<T>(min, max)(engine());
        }
    };
}
