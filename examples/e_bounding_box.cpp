// Axis-aligned bounding boxes: construction from corners or points, growing, intersection and IoU, and
// transformation (a rotated box is re-bounded by the box of its rotated corners).
#include <iostream>
#include <vector>

#include "rtl/Core.h"
#include "rtl/Transformation.h"
#include "rtl/io/StdLib.h"

int main()
{
    // Two opposite corners in any order.
    const rtl::BoundingBox3d unit({-1, -1, -1}, {1, 1, 1});
    const rtl::BoundingBox3d shifted({2, 2, 2}, {0, 0, 0});
    std::cout << "unit: " << unit << ", volume " << unit.volume() << "\nshifted: " << shifted << "\n";

    // The overlap, and intersection over union (1/15 here).
    if (const auto overlap = rtl::BoundingBox3d::intersection(unit, shifted))
        std::cout << "intersection: " << *overlap << ", volume " << overlap->volume() << "\n";
    std::cout << "IoU = " << unit.intersectionOverUnion(shifted) << "\n";

    // Bounding a point set, then growing it.
    std::vector<rtl::Vector2f> pts{{0.5f, 1.0f}, {-2.0f, 0.0f}, {1.0f, -0.5f}};
    rtl::BoundingBox2f box(pts);
    box.addPoint({3.0f, 3.0f});
    std::cout << "2D box: " << box << ", centroid " << box.centroid() << "\n";

    // All corners, and a rotation by 45 degrees about x: x bounds stay, y and z grow to sqrt(2).
    std::cout << "corners of the unit box: " << unit.allVertices().size() << "\n";
    const rtl::RigidTf3d tf(rtl::C_PI_4d, rtl::Vector3d::baseX(), rtl::Vector3d());
    const auto rotated = unit.transformed(tf);
    std::cout << "rotated: " << rotated << "\n";

    const bool ok = unit.intersectionOverUnion(shifted) > 0.066 && unit.intersectionOverUnion(shifted) < 0.067
                    && rotated.max().x() == 1.0 && rotated.max().y() > 1.41;
    return ok ? 0 : 1;
}
