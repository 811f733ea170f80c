// Test module: random generation, per-type tolerances and descriptions, and template-combination testers.
#pragma once

#include "rtl/test/TemplateTester.h"
#include "rtl/test/TypeDetails.h"
#include "rtl/test/Random.h"
