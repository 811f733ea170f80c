// SimpleAgent: a 1-D agent (a value) for GeneticAlgorithm, scored by a fitness function shared by all agents of T.
#pragma once

#include <functional>

#include "rtl/alg/AlgorithmRandom.h"

namespace rtl
{
    template<typename T>
    class SimpleAgent
    {
    public:
        explicit SimpleAgent(T val) : val(val) {}

        //! Uniform in [-100, 100] (AlgorithmRandom).
        static SimpleAgent random() { return SimpleAgent(AlgorithmRandom::uniform(static_cast<T>(-100), static_cast<T>(100))); }

        //! The fitness of the value (set_fit_fn; 1 by default).
        float score() { return fitFn()(val); }

        //! The mean of the two values.
        SimpleAgent crossover(const SimpleAgent<T> &mate) { return SimpleAgent(static_cast<T>((val + mate.val) / static_cast<T>(2))); }

        //! value += uniform in [-1, 1].
        void mutate() { val += AlgorithmRandom::uniform(static_cast<T>(-1), static_cast<T>(1)); }

        //! Fitness used by score() of every SimpleAgent<T>; an empty function restores the default (always 1).
        static void set_fit_fn(const std::function<float(T)> &fn) { fitFn() = fn ? fn : defaultFitFn(); }

        T value() const { return val; }

    private:
        static std::function<float(T)> defaultFitFn() { return [](T) { return 1.0f; }; }
        static std::function<float(T)> &fitFn()
        {
            static std::function<float(T)> fn = defaultFitFn();
            return fn;
        }

        T val;
    };
}
