// Quaternions: rotations from angle-axis, roll-pitch-yaw and two vectors; rotation matrices; slerp.
#include <iostream>

#include "rtl/Core.h"
#include "rtl/io/StdLib.h"

int main()
{
    // A rotation by 90 degrees about z, as angle-axis.
    const rtl::Quaterniond qz(rtl::C_PI_2d, rtl::Vector3d::baseZ());
    std::cout << "qz = " << qz << "\nR(qz) = " << qz.rotMat() << "\n";
    std::cout << "qz rotates x to " << qz.rotMat() * rtl::Vector3d::baseX() << "\n";

    // Roll-pitch-yaw: q = Rx(roll) Ry(pitch) Rz(yaw); rpy() recovers the angles.
    const rtl::Quaterniond q(0.1, -0.4, 2.0);
    double roll, pitch, yaw;
    q.rpy(roll, pitch, yaw);
    std::cout << "q(0.1, -0.4, 2.0) = " << q << " -> rpy " << roll << ", " << pitch << ", " << yaw << "\n";

    // The shortest rotation between two directions.
    const rtl::Quaterniond between(rtl::Vector3d(1, 0, 0), rtl::Vector3d(0, 1, 1));
    std::cout << "x -> (0, 1, 1)/sqrt(2): " << between.rotMat() * rtl::Vector3d::baseX() << "\n";

    // Products, inverses and interpolation.
    std::cout << "q q^-1 = " << q * q.inverted() << "\n";
    for (double s : {0.0, 0.5, 1.0})
        std::cout << "slerp(identity, qz, " << s << ") = " << rtl::Quaterniond::identity().slerp(qz, s) << "\n";

    const bool ok = std::abs(roll - 0.1) < 1e-12 && std::abs(pitch + 0.4) < 1e-12 && std::abs(yaw - 2.0) < 1e-12
                    && rtl::Vector3d::distance(qz.rotMat() * rtl::Vector3d::baseX(), rtl::Vector3d::baseY()) < 1e-12;
    return ok ? 0 : 1;
}
