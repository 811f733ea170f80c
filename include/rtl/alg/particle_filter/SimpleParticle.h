// SimpleParticle: a 1-D particle (a value on a line) for ParticleFilter, and the example of its interface.
#pragma once

#include <cmath>
#include <vector>

#include "rtl/alg/AlgorithmRandom.h"

namespace rtl
{
    template<typename T>
    class SimpleParticle
    {
    public:
        class Action
        {
        public:
            explicit Action(const T &v) : val(v) {}
            [[nodiscard]] T value() const { return val; }

        private:
            T val;
        };
        class Measurement
        {
        public:
            explicit Measurement(const T &v) : val(v) {}
            [[nodiscard]] T value() const { return val; }

        private:
            T val;
        };
        class Result
        {
        public:
            explicit Result(T mean, T std_dev) : m(mean), s(std_dev) {}
            [[nodiscard]] T mean() const { return m; }
            [[nodiscard]] T std_dev() const { return s; }

        private:
            T m, s;
        };

        explicit SimpleParticle(T val) : value(val) {}

        //! Uniform in [-100, 100] (AlgorithmRandom).
        static SimpleParticle random() { return SimpleParticle(AlgorithmRandom::uniform(static_cast<T>(-100), static_cast<T>(100))); }

        void move(const Action &action) { value += action.value(); }

        //! Gaussian likelihood (sigma = 10) of the distance between the value and the measurement.
        [[nodiscard]] float belief(const Measurement &measurement)
        {
            constexpr double sigma = 10.0;
            const double d = static_cast<double>(value) - static_cast<double>(measurement.value());
            return static_cast<float>(std::exp(-d * d / (2 * sigma * sigma)) / (sigma * std::sqrt(2 * 3.14159265358979323846)));
        }

        //! Mean and population standard deviation of the values; {0, 0} for no particles.
        [[nodiscard]] static Result evaluation(const std::vector<SimpleParticle> &particles)
        {
            if (particles.empty())
                return Result(T(0), T(0));
            double sum = 0;
            for (const SimpleParticle &p : particles)
                sum += static_cast<double>(p.value);
            const double mean = sum / static_cast<double>(particles.size());
            double sq = 0;
            for (const SimpleParticle &p : particles)
                sq += (static_cast<double>(p.value) - mean) * (static_cast<double>(p.value) - mean);
            return Result(static_cast<T>(mean), static_cast<T>(std::sqrt(sq / static_cast<double>(particles.size()))));
        }

    private:
        T value;
    };
}
