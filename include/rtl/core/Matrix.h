// Matrix: a rows x cols matrix on top of Eigen (Eigen::Dynamic sizes allowed, see MatrixD in rtl/Core.h).
// Default construction zero-initialises fixed-size matrices; a dynamic one starts empty.
//
// Complexity: element-wise operations O(rows * cols); products, inversion, determinant and eigen-decomposition as
// Eigen's (O(n^3) for n x n). Fixed sizes never allocate; Eigen::Dynamic sizes allocate like Eigen::MatrixX.
// Preconditions: invert()/inverted() need a non-singular matrix (otherwise inf/NaN elements, as Eigen); operations
// restricted to square or fixed-size matrices are rejected at compile time (static_assert), not at run time.
#pragma once

#include <complex>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "rtl/core/VectorND.h"

namespace rtl
{
    template<int rows, int cols, typename Element>
    class Matrix
    {
    public:
        typedef Element ElementType;
        typedef Element DistanceType;
        typedef Eigen::Matrix<Element, rows, cols> EigenType;

        template<int, int, typename> friend class Matrix;

        Matrix() : elements(zeroInit()) {}
        //! Size of a dynamic matrix (both dimensions Eigen::Dynamic); the elements are zero.
        Matrix(int r, int c) : elements(EigenType::Zero(r, c))
        {
            static_assert(rows == Eigen::Dynamic && cols == Eigen::Dynamic, "Matrix(rows, cols) is for dynamic matrices only.");
        }
        Matrix(const Matrix &m) = default;
        explicit Matrix(const EigenType &em) : elements(em) {}
        ~Matrix() = default;

        template<typename NewElement>
        [[nodiscard]] Matrix<rows, cols, NewElement> cast() const
        {
            return Matrix<rows, cols, NewElement>(typename Matrix<rows, cols, NewElement>::EigenType(elements.template cast<NewElement>()));
        }

        EigenType &data() { return elements; }
        const EigenType &data() const { return elements; }

        [[nodiscard]] bool hasNaN() const
        {
            static_assert(std::is_floating_point_v<Element>, "hasNaN() needs a floating-point element type.");
            return elements.hasNaN();
        }

        //! Bounds-checked access; throws std::out_of_range.
        Element getElement(size_t r, size_t c) const { return elements(checkedRow(r), checkedCol(c)); }
        void setElement(size_t r, size_t c, Element value) { elements(checkedRow(r), checkedCol(c)) = value; }

        template<int c_ = cols, std::enable_if_t<(c_ > 0), int> = 0>
        VectorND<cols, Element> getRow(size_t r) const
        {
            return VectorND<cols, Element>(typename VectorND<cols, Element>::EigenType(elements.row(checkedRow(r)).transpose()));
        }
        template<int r_ = rows, std::enable_if_t<(r_ > 0), int> = 0>
        VectorND<rows, Element> getColumn(size_t c) const
        {
            return VectorND<rows, Element>(typename VectorND<rows, Element>::EigenType(elements.col(checkedCol(c))));
        }
        template<int c_ = cols, std::enable_if_t<(c_ > 0), int> = 0>
        void setRow(size_t r, const VectorND<c_, Element> &row) { elements.row(checkedRow(r)) = row.data().transpose(); }
        template<int r_ = rows, std::enable_if_t<(r_ > 0), int> = 0>
        void setColumn(size_t c, const VectorND<r_, Element> &column) { elements.col(checkedCol(c)) = column.data(); }

        //! Unchecked access (precondition: indices in range).
        Element &operator()(size_t r, size_t c) { return elements(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)); }
        const Element &operator()(size_t r, size_t c) const { return elements(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)); }

        Matrix &operator=(const Matrix &m) = default;
        Matrix &operator=(const EigenType &em) { elements = em; return *this; }

        //! Exact element-wise comparison; matrices of different (dynamic) sizes are unequal.
        bool operator==(const Matrix &m) const
        {
            return elements.rows() == m.elements.rows() && elements.cols() == m.elements.cols() && elements == m.elements;
        }
        bool operator!=(const Matrix &m) const { return !(*this == m); }

        //! Matrix * column vector, a vector of `rows` elements. (The published version declared the result with `cols`
        //! elements, which is only right for square matrices.)
        template<int c_ = cols, std::enable_if_t<(c_ > 0 && rows > 0), int> = 0>
        VectorND<rows, Element> operator*(const VectorND<c_, Element> &vector) const
        {
            return VectorND<rows, Element>(typename VectorND<rows, Element>::EigenType(elements * vector.data()));
        }
        template<int op_cols>
        Matrix<rows, op_cols, Element> operator*(const Matrix<cols, op_cols, Element> &matrix) const
        {
            return Matrix<rows, op_cols, Element>(typename Matrix<rows, op_cols, Element>::EigenType(elements * matrix.elements));
        }
        Matrix operator*(const Element &scalar) const { return Matrix(EigenType(elements * scalar)); }
        Matrix operator/(const Element &scalar) const { return Matrix(EigenType(elements / scalar)); }
        Matrix &operator*=(const Matrix &matrix)
        {
            static_assert(rows == cols, "operator*=(Matrix) needs a square matrix.");
            elements = (elements * matrix.elements).eval();
            return *this;
        }
        Matrix &operator*=(const Element &scalar) { elements *= scalar; return *this; }
        Matrix &operator/=(const Element &scalar) { elements /= scalar; return *this; }
        Matrix operator+(const Matrix &m) const { return Matrix(EigenType(elements + m.elements)); }
        Matrix &operator+=(const Matrix &m) { elements += m.elements; return *this; }
        Matrix operator-(const Matrix &m) const { return Matrix(EigenType(elements - m.elements)); }
        Matrix &operator-=(const Matrix &m) { elements -= m.elements; return *this; }
        Matrix operator-() const { return Matrix(EigenType(-elements)); }

        void transpose()
        {
            static_assert(rows == cols, "transpose() in place needs a square matrix; use transposed().");
            elements.transposeInPlace();
        }
        [[nodiscard]] Matrix<cols, rows, Element> transposed() const
        {
            return Matrix<cols, rows, Element>(typename Matrix<cols, rows, Element>::EigenType(elements.transpose()));
        }

        //! Precondition: non-singular (a singular matrix yields inf/NaN elements, as Eigen's inverse() does).
        void invert()
        {
            static_assert(rows == cols, "invert() needs a square matrix.");
            elements = elements.inverse().eval();
        }
        [[nodiscard]] Matrix<cols, rows, Element> inverted() const
        {
            static_assert(rows == cols, "inverted() needs a square matrix.");
            return Matrix<cols, rows, Element>(typename Matrix<cols, rows, Element>::EigenType(elements.inverse()));
        }
        Element determinant() const { return elements.determinant(); }
        Element trace() const { return elements.trace(); }

        //! Eigenvalues in the order Eigen::EigenSolver returns them.
        VectorND<rows, std::complex<Element>> eigenvalues() const
        {
            static_assert(rows == cols && rows > 0, "eigenvalues() needs a fixed-size square matrix.");
            Eigen::EigenSolver<EigenType> es(elements, false);
            return VectorND<rows, std::complex<Element>>(typename VectorND<rows, std::complex<Element>>::EigenType(es.eigenvalues()));
        }
        //! Unit eigenvectors as columns, in the order of eigenvalues().
        Matrix<cols, rows, std::complex<Element>> eigenvectors() const
        {
            static_assert(rows == cols && rows > 0, "eigenvectors() needs a fixed-size square matrix.");
            Eigen::EigenSolver<EigenType> es(elements, true);
            return Matrix<cols, rows, std::complex<Element>>(typename Matrix<cols, rows, std::complex<Element>>::EigenType(es.eigenvectors()));
        }

        static constexpr int rowNr() { return rows; }
        static constexpr int colNr() { return cols; }

        static Matrix zeros() { return Matrix(EigenType(EigenType::Zero())); }
        static Matrix ones() { return Matrix(EigenType(EigenType::Ones())); }
        static Matrix identity() { return Matrix(EigenType(EigenType::Identity())); }
        static Matrix nan()
        {
            static_assert(std::is_floating_point_v<Element>, "nan() needs a floating-point element type.");
            return Matrix(EigenType(EigenType::Constant(std::numeric_limits<Element>::quiet_NaN())));
        }

        //! Frobenius norm of m1 - m2.
        static DistanceType distance(const Matrix &m1, const Matrix &m2) { return (m1.elements - m2.elements).norm(); }
        static DistanceType distanceSquared(const Matrix &m1, const Matrix &m2) { return (m1.elements - m2.elements).squaredNorm(); }

        //! Every element is static_cast<Element>(el_rnd_gen()), row by row.
        template<class ElRndSrc, typename = std::enable_if_t<std::is_invocable_v<const ElRndSrc &>>>
        static Matrix random(const ElRndSrc &el_rnd_gen)
        {
            static_assert(rows > 0 && cols > 0, "random() needs a fixed-size matrix.");
            EigenType e;
            for (Eigen::Index r = 0; r < rows; ++r)
                for (Eigen::Index c = 0; c < cols; ++c)
                    e(r, c) = static_cast<Element>(el_rnd_gen());
            return Matrix(e);
        }

    private:
        EigenType elements;

        static EigenType zeroInit()
        {
            if constexpr (rows != Eigen::Dynamic && cols != Eigen::Dynamic)
                return EigenType::Zero();
            else
                return EigenType();
        }
        Eigen::Index checkedRow(size_t r) const
        {
            if (r >= static_cast<size_t>(elements.rows()))
                throw std::out_of_range("rtl::Matrix: row " + std::to_string(r) + " out of range (" + std::to_string(elements.rows()) + " rows)");
            return static_cast<Eigen::Index>(r);
        }
        Eigen::Index checkedCol(size_t c) const
        {
            if (c >= static_cast<size_t>(elements.cols()))
                throw std::out_of_range("rtl::Matrix: column " + std::to_string(c) + " out of range (" + std::to_string(elements.cols()) + " columns)");
            return static_cast<Eigen::Index>(c);
        }
    };

    //! CTAD from any Eigen matrix: rtl::Matrix{Eigen::Matrix<double, 2, 2>{}} is a Matrix<2, 2, double>.
    template<typename E, int R, int C, int O, int MR, int MC>
    Matrix(const Eigen::Matrix<E, R, C, O, MR, MC> &) -> Matrix<R, C, E>;

    //! Row vector * matrix: v^T M, a vector of `cols` elements.
    template<int rows, int cols, typename Element>
    VectorND<cols, Element> operator*(const VectorND<rows, Element> &vector, const Matrix<rows, cols, Element> &matrix)
    {
        return VectorND<cols, Element>(typename VectorND<cols, Element>::EigenType((vector.data().transpose() * matrix.data()).transpose()));
    }

    //! scalar * matrix.
    template<int rows, int cols, typename Element>
    Matrix<rows, cols, Element> operator*(const Element &scalar, const Matrix<rows, cols, Element> &matrix)
    {
        return matrix * scalar;
    }
}
