// Umbrella header of the segmentation module: CAR_Segmenter (batch, closed scans) and IA_Segmenter (streaming),
// which share one proximity criterion (seg/ProximityCriterion.h), and their optional trace events (seg/SegTrace.h:
// rtl::CarTraceLog, rtl::IaTraceLog).
#pragma once

#include <list>
#include <map>
#include <vector>

#include "rtl/Core.h"
#include "rtl/seg/CAR_Segmenter.h"
#include "rtl/seg/IA_Segmenter.h"
#include "rtl/seg/SegTrace.h"
