// Transformations in a nutshell: build, apply, compose, invert, and hold any of them in a GeneralTf.
// The program checks its own results and exits with 1 if any of them is wrong.
#include <iostream>
#include <string>

#include "rtl/Core.h"
#include "rtl/Transformation.h"
#include "rtl/io/StdLib.h"

namespace
{
    int failures = 0;

    template<int d>
    void show(const std::string &what, const rtl::VectorND<d, double> &got, const rtl::VectorND<d, double> &expected)
    {
        const bool ok = rtl::VectorND<d, double>::distance(got, expected) < 1e-12;
        std::cout << what << got;
        if (!ok)
        {
            std::cout << "   <-- WRONG, expected " << expected;
            ++failures;
        }
        std::cout << "\n";
    }
}

int main()
{
    // 2D: rotate 90 degrees counter-clockwise, then shift by (1, 0).
    const rtl::Rotation2d rot(rtl::C_PI_2d);
    const rtl::Translation2d shift(1, 0);
    const rtl::Vector2d p(1, 0);
    show("rot(p)        = ", rot(p), rtl::Vector2d(0, 1));
    const rtl::RigidTf2d both = shift(rot);                          // rot first, then shift: a RigidTf2d
    show("shift(rot)(p) = ", both(p), rtl::Vector2d(1, 1));
    show("inverse       = ", both.inverted()(both(p)), p);

    // 3D: the same rigid transformation from angle-axis, quaternion and roll-pitch-yaw.
    const rtl::RigidTf3d aa(rtl::C_PI_2d, rtl::Vector3d(0, 0, 1), rtl::Vector3d(0, 0, 1));
    const rtl::RigidTf3d quat(aa.rotQuaternion(), aa.trVec());
    const rtl::RigidTf3d rpy(0.0, 0.0, rtl::C_PI_2d, aa.trVec());
    const rtl::Vector3d q(1, 0, 0);
    show("angle-axis:  ", aa(q), rtl::Vector3d(0, 1, 1));
    show("quaternion:  ", quat(q), rtl::Vector3d(0, 1, 1));
    show("rpy:         ", rpy(q), rtl::Vector3d(0, 1, 1));

    // Objects transform like their points.
    const rtl::LineSegment3d seg(rtl::Vector3d(0, 0, 0), rtl::Vector3d(1, 0, 0));
    const rtl::LineSegment3d moved = aa(seg);
    std::cout << "segment: " << moved << "\n";
    show("segment end: ", moved.end(), rtl::Vector3d(0, 1, 1));
    const rtl::BoundingBox3d box(rtl::Vector3d(0, 0, 0), rtl::Vector3d(2, 1, 1));
    show("box max:     ", aa(box).max(), rtl::Vector3d(0, 2, 2));

    // A GeneralTf holds any of several types and dispatches at run time.
    using GTf = rtl::GeneralTf<rtl::Translation3d, rtl::Rotation3d, rtl::RigidTf3d>;
    GTf g = rtl::Translation3d(1, 2, 3);
    show("general (translation): ", g(q), rtl::Vector3d(2, 2, 3));
    g = aa;
    show("general (rigid):       ", g(q), rtl::Vector3d(0, 1, 1));
    // Composing two GeneralTfs: the argument first, then this one.
    const GTf composed = GTf(rtl::Translation3d(1, 2, 3))(g);
    show("composed:              ", composed(q), rtl::Vector3d(1, 3, 4));
    std::cout << "composed holds alternative " << composed.index() << " (RigidTf3d)\n";
    failures += composed.index() == 2 ? 0 : 1;
    return failures == 0 ? 0 : 1;
}
