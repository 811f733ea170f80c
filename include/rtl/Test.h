// Test module: random generation, per-type tolerances and descriptions, and template-combination testers.
#pragma once

// Standard names that test code written against RTL uses after including only rtl/Transformation.h and rtl/Test.h.
#include <iostream>
#include <limits>
#include <list>
#include <map>
#include <random>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "rtl/test/TemplateTester.h"
#include "rtl/test/TypeDetails.h"
#include "rtl/test/Random.h"
