// libFuzzer harness for CAR_Segmenter (rtl/seg/CAR_Segmenter.h), 2D and 3D, float and double. The input is a
// program: the first byte picks the vector type, then each opcode byte (with its operands) adds points, changes a
// parameter, segments the scan, grabs clusters, or copies / moves / copy-assigns the segmenter and goes on with the
// copy (the source destroyed). Every loadData is compared with a brute-force model of the documented criterion
// written here: point i is linked to i - k (indices modulo N) for 1 <= k <= step - 1 when both are finite and
// |p_i - p_j|^2 <= clamp(s^2 |p_i - o|^2, lb^2, ub^2), s = step * 2 pi / N; clusters are the connected components,
// handed out by smallest index, each in scan order but rotated to start after its one gap of more than step - 1
// indices (the seam). Equality of the handed-out clusters, point for point, also proves that nothing is lost.
// Bad bounds or a non-finite origin must throw std::invalid_argument and nothing else.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "rtl/seg/CAR_Segmenter.h"
#include "fuzz_common.h"

namespace
{
    using fuzz::Bytes;
    using fuzz::require;

    template<class V>
    struct Model
    {
        using E = typename V::ElementType;
        static constexpr int D = V::dimensionality();

        static bool finite(const V &v)
        {
            for (int k = 0; k < D; ++k)
                if (!std::isfinite(v[static_cast<std::size_t>(k)])) return false;
            return true;
        }

        static E sq(const V &a, const V &b)
        {
            E s = 0;
            for (int k = 0; k < D; ++k)
            {
                const E d = a[static_cast<std::size_t>(k)] - b[static_cast<std::size_t>(k)];
                s += d * d;
            }
            return s;
        }

        //! The documented criterion, the threshold belonging to the later point i.
        static bool linked(const V &later, const V &earlier, const V &origin, E scaling, E lb, E ub)
        {
            E t = scaling * scaling * sq(later, origin);
            t = t < lb * lb ? lb * lb : t;
            t = t > ub * ub ? ub * ub : t;
            return sq(later, earlier) <= t;
        }

        static std::size_t find(std::vector<std::size_t> &p, std::size_t x)
        {
            while (p[x] != x) x = p[x] = p[p[x]];
            return x;
        }

        static std::vector<std::vector<V>> clusters(const std::vector<V> &pts, const V &origin, std::size_t step, E lb, E ub)
        {
            const std::size_t n = pts.size();
            if (n == 0) return {};
            const E scaling = static_cast<E>(2.0 * 3.14159265358979323846264338327950288 * static_cast<double>(step) / static_cast<double>(n));
            std::vector<std::size_t> parent(n);
            std::iota(parent.begin(), parent.end(), std::size_t(0));
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t k = 1; k + 1 <= step && k < n; ++k)
                {
                    const std::size_t j = (i + n - k) % n;
                    if (finite(pts[i]) && finite(pts[j]) && linked(pts[i], pts[j], origin, scaling, lb, ub))
                    {
                        const std::size_t a = find(parent, i), b = find(parent, j);
                        if (a != b) parent[std::max(a, b)] = std::min(a, b);
                    }
                }
            std::vector<std::vector<std::size_t>> members(n);
            std::vector<std::size_t> roots;
            for (std::size_t i = 0; i < n; ++i)
                if (finite(pts[i]))
                {
                    const std::size_t r = find(parent, i);
                    if (members[r].empty()) roots.push_back(r);   // roots appear in order of their smallest index
                    members[r].push_back(i);
                }
            std::vector<std::vector<V>> out;
            for (std::size_t r : roots)
            {
                const auto &m = members[r];
                std::size_t start = 0;
                for (std::size_t k = 1; k < m.size(); ++k)
                    if (m[k] - m[k - 1] > step - 1) start = k;   // the seam: the cluster starts with its end part
                std::vector<V> c;
                for (std::size_t k = 0; k < m.size(); ++k) c.push_back(pts[m[(start + k) % m.size()]]);
                out.push_back(c);
            }
            return out;
        }
    };

    template<class V>
    void run(Bytes in)
    {
        using E = typename V::ElementType;
        constexpr int D = V::dimensionality();
        auto car = std::make_unique<rtl::CAR_Segmenter<V>>();
        std::size_t step = 2;
        E lb = 0, ub = std::numeric_limits<E>::infinity();
        typename V::EigenType o = V::zeros().data();
        std::vector<V> pts;
        V last = V::zeros();
        std::vector<std::vector<V>> expected;   // what the segmenter still has to hand out, in order
        std::size_t next = 0;

        while (!in.empty())
        {
            switch (in.next() % 11)
            {
            case 0:
                step = in.next() % 14;
                car->setStepSize(step);
                step = step == 0 ? 1 : step;
                break;
            case 1:
            {
                const std::uint8_t b = in.next();
                lb = b == 255 ? E(-1) : static_cast<E>(b) / E(64);
                car->setLowerBound(lb);
                break;
            }
            case 2:
            {
                const std::uint8_t b = in.next();
                ub = b == 255 ? std::numeric_limits<E>::infinity() : static_cast<E>(b) / E(32);
                car->setUpperBound(ub);
                break;
            }
            case 3:   // points: a walk with small steps (clusters), jumps and gaps
            {
                const std::size_t m = in.next();
                for (std::size_t i = 0; i < m && !in.empty() && pts.size() < 4096; ++i)
                {
                    typename V::EigenType e = last.data();
                    bool gap = false;
                    for (int k = 0; k < D; ++k)
                    {
                        const std::uint8_t b = in.next();
                        if (b == 0x80) gap = true;
                        e[k] = static_cast<E>(e[k] + static_cast<E>(static_cast<std::int8_t>(b)) / E(32));
                    }
                    if (gap) pts.push_back(V::nan());
                    else
                    {
                        last = V(e);
                        pts.push_back(last);
                    }
                }
                break;
            }
            case 4:   // repeat the last few points (duplicates and constant runs)
            {
                const std::size_t m = in.next() % 32;
                for (std::size_t i = 0; i < m && !pts.empty() && pts.size() < 4096; ++i) pts.push_back(pts[pts.size() - 1 - i % pts.size()]);
                break;
            }
            case 5:
                pts.clear();
                break;
            case 6:
            {
                const std::uint8_t b = in.next();
                for (int k = 0; k < D; ++k) o[k] = static_cast<E>(static_cast<std::int8_t>(in.next())) / E(16);
                if (b == 0x80) o[0] = std::numeric_limits<E>::quiet_NaN();
                if (b == 0x81) o[D - 1] = std::numeric_limits<E>::infinity();
                break;
            }
            case 7:   // segment
            {
                const V origin(o);
                const bool bad = !(lb >= E(0)) || !(ub >= lb) || !Model<V>::finite(origin);
                try
                {
                    car->loadData(pts, origin);
                    require(!bad);
                }
                catch (const std::invalid_argument &)
                {
                    require(bad);
                    break;
                }
                expected = Model<V>::clusters(pts, origin, step, lb, ub);
                next = 0;
                require(car->clustersAvailable() == expected.size());
                break;
            }
            case 8:   // grab some clusters
            {
                std::size_t m = in.next() % 8;
                for (; m > 0; --m)
                {
                    const std::vector<V> c = car->grabCluster();
                    if (next == expected.size())
                    {
                        require(c.empty());
                        break;
                    }
                    require(c == expected[next++]);
                    require(car->clustersAvailable() == expected.size() - next);
                }
                break;
            }
            case 9:   // copy, copy-assign or move, then go on with the copy only
            {
                const std::uint8_t how = in.next() % 3;
                std::unique_ptr<rtl::CAR_Segmenter<V>> copy;
                if (how == 0) copy = std::make_unique<rtl::CAR_Segmenter<V>>(*car);
                else if (how == 1)
                {
                    copy = std::make_unique<rtl::CAR_Segmenter<V>>(3, E(1), E(2));
                    copy->loadData(std::vector<V>(3, V::zeros()));
                    *copy = *car;
                }
                else copy = std::make_unique<rtl::CAR_Segmenter<V>>(std::move(*car));
                if (how == 2) require(car->clustersAvailable() == 0);
                car = std::move(copy);
                require(car->clustersAvailable() == expected.size() - next);
                break;
            }
            case 10:
                car->setMaxSize(in.next());
                break;
            }
        }
        // drain: everything left comes out exactly
        while (next < expected.size()) require(car->grabCluster() == expected[next++]);
        require(car->clustersAvailable() == 0 && car->grabCluster().empty());
    }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0) return 0;
    Bytes in{data + 1, size - 1};
    switch (data[0] % 4)
    {
    case 0: run<rtl::VectorND<2, float>>(in); break;
    case 1: run<rtl::VectorND<3, float>>(in); break;
    case 2: run<rtl::VectorND<2, double>>(in); break;
    default: run<rtl::VectorND<3, double>>(in); break;
    }
    return 0;
}
