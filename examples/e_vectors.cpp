// Vectors: construction, arithmetic, products, projections and angles with rtl::VectorND and its 2D/3D aliases.
#include <iostream>

#include "rtl/Core.h"
#include "rtl/io/StdLib.h"

int main()
{
    // Default construction gives the zero vector; the 2D/3D element constructors also accept brace lists.
    rtl::Vector3d zero;
    rtl::Vector3d a(1.0, 2.0, 3.0), b{-2.0, 0.5, 1.0};
    std::cout << "zero = " << zero << ", a = " << a << ", b = " << b << "\n";

    // Element-wise arithmetic and scaling.
    std::cout << "a + b = " << a + b << ", a - b = " << a - b << ", 2 a = " << 2.0 * a << ", a / 4 = " << a / 4.0 << "\n";

    // Products: dot, cross (3D), outer (a matrix).
    std::cout << "a . b = " << a.dot(b) << ", a x b = " << a.cross(b) << "\n";
    std::cout << "a b^T = " << a.outer(b) << "\n";

    // Lengths, distances and projections.
    std::cout << "|a| = " << a.length() << ", |a - b| = " << rtl::Vector3d::distance(a, b) << "\n";
    std::cout << "projection of a on b: " << rtl::Vector3d::vectorProjection(a, b)
              << " (signed length " << rtl::Vector3d::scalarProjection(a, b) << ")\n";

    // Angles: unsigned between any two vectors, signed (counter-clockwise) in 2D.
    std::cout << "angle(a, b) = " << rtl::Vector3d::angleShortest(a, b) << " rad\n";
    rtl::Vector2f u = rtl::Vector2f::baseX(), v{0.0f, 2.0f};
    std::cout << "angleCcw(" << u << ", " << v << ") = " << rtl::Vector2f::angleCcw(u, v)
              << ", angleCcw back = " << rtl::Vector2f::angleCcw(v, u) << "\n";

    // Any dimension works; element-wise construction is explicit there.
    rtl::VectorND<5, float> five(1, 2, 3, 4, 5);
    std::cout << "five = " << five << ", normalised = " << five.normalized() << "\n";

    const bool ok = zero == rtl::Vector3d::zeros() && a.cross(b).dot(a) < 1e-12 && rtl::Vector2f::angleCcw(u, v) > 0;
    return ok ? 0 : 1;
}
