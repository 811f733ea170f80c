// GeneticAlgorithm: find the maximum of a fitness function over the real line with SimpleAgent.
#include <iostream>

#include "rtl/Algorithms.h"

int main()
{
    using Agent = rtl::SimpleAgent<float>;
    Agent::set_fit_fn([](float v) { return 1.0f / (std::abs(v - 3.0f) + 0.001f); });    // peak at 3
    rtl::AlgorithmRandom::seed(2024);       // reproducible run

    rtl::GeneticAlgorithm<Agent, 100, 5, 30, 10> ga;    // 100 agents, 5 elites, 30 survivors, 10 mutations per epoch
    for (int epoch = 1; epoch <= 60; ++epoch)
    {
        ga.iterate_epoch();
        if (epoch % 20 == 0)
            std::cout << "epoch " << epoch << ": best " << ga.best_agent().value() << "\n";
    }
    return std::abs(ga.best_agent().value() - 3.0f) < 0.1f ? 0 : 1;
}
