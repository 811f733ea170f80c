// Umbrella header of the transformation module: N-D translations, rotations and rigid transformations, the generic
// GeneralTf holder, transformation chains and trees, and the 2D/3D aliases
// (docs/reference.md, "Transformation aliases").
#pragma once

// Standard headers that code using the transformation module (and its tests) relies on transitively
// (docs/reference.md, "Umbrella headers and transitive includes").
#include <limits>
#include <list>
#include <map>
#include <random>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "rtl/tf/TranslationND.h"
#include "rtl/tf/RotationND.h"
#include "rtl/tf/RigidTfND.h"
#include "rtl/tf/TfTree.h"
#include "rtl/tf/TfChain.h"

namespace rtl
{
    template<typename T> using Translation2D = TranslationND<2, T>;
    using Translation2f = Translation2D<float>;
    using Translation2d = Translation2D<double>;
    template<typename T> using Translation3D = TranslationND<3, T>;
    using Translation3f = Translation3D<float>;
    using Translation3d = Translation3D<double>;

    template<typename T> using Rotation2D = RotationND<2, T>;
    using Rotation2f = Rotation2D<float>;
    using Rotation2d = Rotation2D<double>;
    template<typename T> using Rotation3D = RotationND<3, T>;
    using Rotation3f = Rotation3D<float>;
    using Rotation3d = Rotation3D<double>;

    template<typename T> using RigidTf2D = RigidTfND<2, T>;
    using RigidTf2f = RigidTf2D<float>;
    using RigidTf2d = RigidTf2D<double>;
    template<typename T> using RigidTf3D = RigidTfND<3, T>;
    using RigidTf3f = RigidTf3D<float>;
    using RigidTf3d = RigidTf3D<double>;
}
