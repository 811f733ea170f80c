// libFuzzer harness for IA_Segmenter (rtl/seg/IA_Segmenter.h), 2D and 3D, float and double. The input is a
// program: the first byte picks the vector type, then each opcode byte (with its operands) adds points, changes the
// step, bounds, scaling or origin mid-stream, grabs closed clusters, checks the alive map, flushes, or copies /
// copy-assigns / moves the segmenter and goes on with the copy (the source destroyed).
// A brute-force model of the documented stream runs alongside: the window holds the last `step` points; a new point
// p is linked to every finite window point q with |p - q|^2 <= clamp(s^2 |p - o|^2, lb^2, ub^2) (parameters at the
// time of the call); components merge completely and keep the oldest id; a point leaving the window (oldest first,
// also when the step shrinks and on flush) goes to its component's alive list; a component with no window point left
// closes. The handed-out closed clusters (order and points), the alive map (ids and points) and the counts must match
// the model exactly, which also proves that nothing is lost. Bad parameters or a non-finite origin must make addPoint
// throw std::invalid_argument and change nothing.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <vector>

#include "rtl/seg/IA_Segmenter.h"
#include "fuzz_common.h"

namespace
{
    using fuzz::Bytes;
    using fuzz::require;

    template<class V>
    class Model
    {
    public:
        using E = typename V::ElementType;
        static constexpr int D = V::dimensionality();

        std::size_t step = 1;
        E lb = 0, ub = std::numeric_limits<E>::infinity(), scaling = E(0.05);

        static bool finite(const V &v)
        {
            for (int k = 0; k < D; ++k)
                if (!std::isfinite(v[static_cast<std::size_t>(k)])) return false;
            return true;
        }

        bool badParameters(const V &origin) const { return !(lb >= E(0)) || !(ub >= lb) || std::isnan(scaling) || !finite(origin); }

        void add(const V &p, const V &origin)
        {
            const std::size_t i = pts_.size();
            pts_.push_back(p);
            parent_.push_back(i);
            in_window_.push_back(1);
            closed_flag_.push_back(0);
            id_.push_back(0);
            if (finite(p))
            {
                bool joined = false;
                for (std::size_t w : window_)
                    if (finite(pts_[w]) && linked(p, pts_[w], origin))
                    {
                        unite(i, w);
                        joined = true;
                    }
                if (!joined) id_[i] = next_id_++;
            }
            window_.push_back(i);
            shrinkTo(step);
        }

        void setStep(std::size_t s)
        {
            step = s == 0 ? 1 : s;
            shrinkTo(step);
        }

        void flush() { shrinkTo(0); }

        //! The alive map the documentation promises: per open component, its points out of the window.
        std::map<std::size_t, std::vector<V>> alive()
        {
            std::map<std::size_t, std::vector<V>> m;
            for (std::size_t i = 0; i < pts_.size(); ++i)
                if (!in_window_[i] && finite(pts_[i]))
                {
                    const std::size_t r = find(i);
                    if (!closed_flag_[r]) m[id_[r]].push_back(pts_[i]);
                }
            return m;
        }

        std::deque<std::vector<V>> closed;   // closed, not yet grabbed, in closing order

    private:
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

        bool linked(const V &later, const V &earlier, const V &origin) const
        {
            E t = scaling * scaling * sq(later, origin);
            t = t < lb * lb ? lb * lb : t;
            t = t > ub * ub ? ub * ub : t;
            return sq(later, earlier) <= t;
        }

        std::size_t find(std::size_t x)
        {
            while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
            return x;
        }

        // the root is the smallest index, which is the oldest component: its id survives
        void unite(std::size_t a, std::size_t b)
        {
            a = find(a);
            b = find(b);
            if (a == b) return;
            if (a > b) std::swap(a, b);
            parent_[b] = a;
        }

        void shrinkTo(std::size_t size)
        {
            while (window_.size() > size)
            {
                const std::size_t w = window_.front();
                window_.pop_front();
                in_window_[w] = 0;
                if (!finite(pts_[w])) continue;
                const std::size_t r = find(w);
                bool open = false;
                for (std::size_t v : window_) open |= finite(pts_[v]) && find(v) == r;
                if (open) continue;
                closed_flag_[r] = 1;
                std::vector<V> c;
                for (std::size_t i = r; i < pts_.size(); ++i)
                    if (finite(pts_[i]) && find(i) == r) c.push_back(pts_[i]);
                closed.push_back(c);
            }
        }

        std::vector<V> pts_;
        std::vector<std::size_t> parent_, id_;
        std::vector<char> in_window_, closed_flag_;
        std::deque<std::size_t> window_;
        std::size_t next_id_ = 0;
    };

    template<class V>
    void run(Bytes in)
    {
        using E = typename V::ElementType;
        using IA = rtl::IA_Segmenter<V>;
        constexpr int D = V::dimensionality();
        Model<V> model;
        auto ia = std::make_unique<IA>(1, model.lb, model.ub, model.scaling);
        typename V::EigenType o = V::zeros().data();
        V last = V::zeros();
        std::size_t added = 0;

        auto checkAlive = [&] {
            const auto expected = model.alive();
            require(ia->aliveClustersAvailable() == expected.size());
            require(ia->aliveClusters() == expected);
        };
        auto add = [&](const V &p) {
            const V origin(o);
            const bool bad = model.badParameters(origin);
            try
            {
                ia->addPoint(p, origin);
                require(!bad);
            }
            catch (const std::invalid_argument &)
            {
                require(bad);
                return;
            }
            model.add(p, origin);
            ++added;
            require(ia->closedClustersAvailable() == model.closed.size());
        };

        while (!in.empty())
        {
            switch (in.next() % 12)
            {
            case 0:
            {
                const unsigned s = in.next() % 14;
                ia->setStepSize(s);
                model.setStep(s);
                require(ia->closedClustersAvailable() == model.closed.size());
                break;
            }
            case 1:
            {
                const std::uint8_t b = in.next();
                model.lb = b == 255 ? E(-1) : static_cast<E>(b) / E(64);
                ia->setLowerBound(model.lb);
                break;
            }
            case 2:
            {
                const std::uint8_t b = in.next();
                model.ub = b == 255 ? std::numeric_limits<E>::infinity() : static_cast<E>(b) / E(32);
                ia->setUpperBound(model.ub);
                break;
            }
            case 3:
            {
                const std::uint8_t b = in.next();
                model.scaling = b == 0x80 ? std::numeric_limits<E>::quiet_NaN() : static_cast<E>(static_cast<std::int8_t>(b)) / E(256);
                ia->setScaling(model.scaling);
                break;
            }
            case 4:   // points: a walk with small steps (clusters), jumps and gaps
            {
                const std::size_t m = in.next();
                for (std::size_t i = 0; i < m && !in.empty() && added < 4096; ++i)
                {
                    typename V::EigenType e = last.data();
                    bool gap = false;
                    for (int k = 0; k < D; ++k)
                    {
                        const std::uint8_t b = in.next();
                        if (b == 0x80) gap = true;
                        e[k] = static_cast<E>(e[k] + static_cast<E>(static_cast<std::int8_t>(b)) / E(32));
                    }
                    if (!gap) last = V(e);
                    add(gap ? V::nan() : last);
                }
                break;
            }
            case 5:   // a run of one repeated point
            {
                const std::size_t m = in.next() % 32;
                for (std::size_t i = 0; i < m && added < 4096; ++i) add(last);
                break;
            }
            case 6:
            {
                const std::uint8_t b = in.next();
                for (int k = 0; k < D; ++k) o[k] = static_cast<E>(static_cast<std::int8_t>(in.next())) / E(16);
                if (b == 0x80) o[0] = std::numeric_limits<E>::quiet_NaN();
                if (b == 0x81) o[D - 1] = -std::numeric_limits<E>::infinity();
                break;
            }
            case 7:   // grab some closed clusters
            {
                for (std::size_t m = in.next() % 8; m > 0; --m)
                {
                    const std::vector<V> c = ia->grabCluster();
                    if (model.closed.empty())
                    {
                        require(c.empty());
                        break;
                    }
                    require(!c.empty() && c == model.closed.front());
                    model.closed.pop_front();
                    require(ia->closedClustersAvailable() == model.closed.size());
                }
                break;
            }
            case 8:
                checkAlive();
                break;
            case 9:
                ia->flush();
                model.flush();
                require(ia->aliveClustersAvailable() == 0 && ia->closedClustersAvailable() == model.closed.size());
                break;
            case 10:   // copy, copy-assign, move or move-assign; go on with the new object, the old one destroyed
            {
                const std::uint8_t how = in.next() % 4;
                std::unique_ptr<IA> copy;
                if (how == 0) copy = std::make_unique<IA>(*ia);
                else if (how == 2) copy = std::make_unique<IA>(std::move(*ia));
                else
                {
                    copy = std::make_unique<IA>(4, E(0), E(1), E(0.5));   // some state for the assignment to replace
                    for (int k = 0; k < 9; ++k) copy->addPoint(V::zeros());
                    if (how == 1) *copy = *ia;
                    else *copy = std::move(*ia);
                }
                ia = std::move(copy);
                require(ia->closedClustersAvailable() == model.closed.size());
                break;
            }
            case 11:   // a copy taken now must end like the original: run both to the end of a flush
            {
                IA copy(*ia);
                copy.flush();
                std::size_t m = 0;
                for (; copy.closedClustersAvailable() > 0; ++m) require(!copy.grabCluster().empty());
                require(m >= model.closed.size());
                break;
            }
            }
        }
        checkAlive();
        ia->flush();
        model.flush();
        require(ia->aliveClustersAvailable() == 0 && ia->aliveClusters().empty());
        while (!model.closed.empty())
        {
            require(ia->grabCluster() == model.closed.front());
            model.closed.pop_front();
        }
        require(ia->closedClustersAvailable() == 0 && ia->grabCluster().empty());
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
