// Vectorization: ordered point chains -> line segments (2D, 3D) or plane polygons (3D).
//
// Every Vectorizer* runs a fixed pipeline of the vect/ stages and returns false as soon as a stage fails; the
// results of the last call stay available through approximations(), indices() and the output accessor.
// Common preconditions, checked: at least 2 points, all coordinates finite, sigma > 0 (and delta > 0 where
// used); otherwise operator() returns false and the outputs are empty. Defaults: sigma 0.03, delta 3.
// setMaxSize(n) sizes the internal buffers for chains of up to n points, so later calls do not allocate for them.
#pragma once

#include <cmath>
#include <limits>
#include <list>
#include <map>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "rtl/Core.h"
#include "rtl/core/Trace.h"
#include "rtl/vect/ApproximationTlsLine2D.h"
#include "rtl/vect/ApproximationTlsLine3D.h"
#include "rtl/vect/ApproximationTlsPlane3D.h"
#include "rtl/vect/ExtractorChainFast.h"
#include "rtl/vect/ExtractorChainIncremental.h"
#include "rtl/vect/FastPolylinePipeline2D.h"
#include "rtl/vect/FtlsTrace.h"
#include "rtl/vect/OptimizerContinuity2D.h"
#include "rtl/vect/OptimizerTotalError.h"
#include "rtl/vect/PostprocessorPolyline2D.h"
#include "rtl/vect/PostprocessorProjectEndpoints.h"
#include "rtl/vect/PrecArray.h"
#include "rtl/vect/PrecArrayBlocked.h"
#include "rtl/vect/PrecSums.h"
#include "rtl/vect/ScanPolylines2D.h"
#include "rtl/vect/SimplifyCompatible.h"
#include "rtl/vect/SimplifyTrace.h"
#include "rtl/vect/VectorizerBase.h"
#include "rtl/vect/VectorizerFast3D.h"
#include "rtl/vect/VectorizerFastPolyline2D.h"
#include "rtl/vect/VectorizerIncremental.h"
#include "rtl/vect/VectorizerPointElimination.h"
