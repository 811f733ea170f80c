// Frustum3D: a viewing frustum given by its apex (origin), the four corners of the near plane and the depth from
// the near plane to the far plane (measured along the ray through the near plane's midpoint).
//
// Precondition: the near plane's midpoint differs from the apex (otherwise the far corners are NaN).
// Complexity: O(1). Transformations move the apex and the near corners and keep the depth; the far corners are
// computed on demand in one fixed formula (farPoint), so equal inputs give bit-identical corners.
#pragma once

#include <Eigen/Dense>

#include "rtl/core/VectorND.h"

namespace rtl
{
    template<int, typename> class TranslationND;
    template<int, typename> class RotationND;
    template<int, typename> class RigidTfND;

    template<typename Element>
    class Frustum3D
    {
    public:
        typedef Element ElementType;
        typedef VectorND<3, Element> VectorType;

        //! Precondition: the near corners differ from the origin, and their mean differs from it too.
        Frustum3D(const VectorType &origin, const VectorType &nearTopLeft, const VectorType &nearTopRight,
                  const VectorType &nearBottomLeft, const VectorType &nearBottomRight, Element depth)
                : int_origin(origin), int_ntl(nearTopLeft), int_ntr(nearTopRight), int_nbl(nearBottomLeft), int_nbr(nearBottomRight), int_depth(depth) {}
        Frustum3D(const Frustum3D<Element> &f) = default;
        Frustum3D &operator=(const Frustum3D &f) = default;

        [[nodiscard]] VectorType getOrigin() const { return int_origin; }
        [[nodiscard]] VectorType getNearTopLeft() const { return int_ntl; }
        [[nodiscard]] VectorType getNearTopRight() const { return int_ntr; }
        [[nodiscard]] VectorType getNearBottomLeft() const { return int_nbl; }
        [[nodiscard]] VectorType getNearBottomRight() const { return int_nbr; }
        [[nodiscard]] VectorType getFarTopLeft() const { return farPoint(int_ntl); }
        [[nodiscard]] VectorType getFarTopRight() const { return farPoint(int_ntr); }
        [[nodiscard]] VectorType getFarBottomLeft() const { return farPoint(int_nbl); }
        [[nodiscard]] VectorType getFarBottomRight() const { return farPoint(int_nbr); }
        //! The mean of the four near corners.
        [[nodiscard]] VectorType getNearMidPoint() const { return (int_ntl + int_ntr + int_nbl + int_nbr) / Element(4); }
        [[nodiscard]] ElementType getDepth() const { return int_depth; }

        // Transformations move the origin and the near corners; the depth is unchanged.
        [[nodiscard]] Frustum3D transformed(const TranslationND<3, Element> &tr) const { Frustum3D f(*this); f.transform(tr); return f; }
        void transform(const TranslationND<3, Element> &tr) { apply(tr); }
        [[nodiscard]] Frustum3D transformed(const RotationND<3, Element> &rot) const { Frustum3D f(*this); f.transform(rot); return f; }
        void transform(const RotationND<3, Element> &rot) { apply(rot); }
        [[nodiscard]] Frustum3D transformed(const RigidTfND<3, Element> &tf) const { Frustum3D f(*this); f.transform(tf); return f; }
        void transform(const RigidTfND<3, Element> &tf) { apply(tf); }

        static constexpr int dimensionality() { return 3; }

    private:
        VectorType int_origin, int_ntl, int_ntr, int_nbl, int_nbr;
        Element int_depth;

        // far = origin + (near - origin) * (L + depth) / L, with L = |nearMid - origin|. Kept in exactly this form:
        // callers compare far corners bit for bit.
        VectorType farPoint(const VectorType &near) const
        {
            const Element l = (getNearMidPoint() - int_origin).length();
            const Element scale = (l + int_depth) / l;
            return int_origin + (near - int_origin) * scale;
        }

        template<typename Tf>
        void apply(const Tf &tf)
        {
            int_origin.transform(tf);
            int_ntl.transform(tf);
            int_ntr.transform(tf);
            int_nbl.transform(tf);
            int_nbr.transform(tf);
        }
    };
}
