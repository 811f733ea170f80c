// Matrices: construction from Eigen (with class template argument deduction), rows and columns, algebra,
// inverse, determinant and eigen-decomposition.
#include <iostream>

#include <Eigen/Dense>

#include "rtl/Core.h"
#include "rtl/io/StdLib.h"

int main()
{
    // Deduces rtl::Matrix<2, 2, double> from the Eigen matrix.
    Eigen::Matrix<double, 2, 2> e;
    e << 4, 1, 2, 3;
    rtl::Matrix mat2x2{e};
    std::cout << "M = " << mat2x2 << "\n";

    // Rows and columns take vectors; brace lists work for 2D/3D.
    mat2x2.setRow(0, {1, 2});
    std::cout << "after setRow(0, {1, 2}): " << mat2x2 << ", column 1 = " << mat2x2.getColumn(1) << "\n";

    // Algebra: products with matrices, vectors and scalars.
    const auto id = rtl::Matrix22d::identity();
    std::cout << "M I + 0 = " << mat2x2 * id + rtl::Matrix22d::zeros() << ", 2 M = " << 2.0 * mat2x2
              << ", M (1, 1) = " << mat2x2 * rtl::Vector2d(1, 1) << "\n";

    // Inverse, determinant, trace.
    std::cout << "det = " << mat2x2.determinant() << ", trace = " << mat2x2.trace() << ", inverse = " << mat2x2.inverted()
              << ", M M^-1 = " << mat2x2 * mat2x2.inverted() << "\n";

    // Eigenvalues and eigenvectors come out complex.
    std::cout << "eigenvalues = " << mat2x2.eigenvalues() << "\neigenvectors = " << mat2x2.eigenvectors() << "\n";

    // Integer matrices and casts.
    const auto ints = 5 * rtl::Matrix<3, 3, int>::ones();
    std::cout << "5 ones = " << ints << ", cast of M to int = " << mat2x2.cast<int>() << "\n";

    const bool ok = rtl::Matrix22d::distance(mat2x2 * mat2x2.inverted(), id) < 1e-12 && ints.trace() == 15;
    return ok ? 0 : 1;
}
