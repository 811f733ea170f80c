// Algorithms module: Kalman filter, Munkres (Hungarian) assignment, particle filter and genetic algorithm,
// plus the runtime-size additions KalmanX and solveAssignment.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <random>
#include <vector>

#include "rtl/Core.h"     // Matrix, VectorND and their aliases, used with the algorithms

#include "rtl/alg/kalman/Kalman.h"
#include "rtl/alg/kalman/KalmanX.h"
#include "rtl/alg/munkres/Assignment.h"
#include "rtl/alg/munkres/Munkres.h"
#include "rtl/alg/particle_filter/ParticleFilter.h"
#include "rtl/alg/particle_filter/SimpleParticle.h"
#include "rtl/alg/genetic/GeneticAlgorithm.h"
#include "rtl/alg/genetic/SimpleAgent.h"
