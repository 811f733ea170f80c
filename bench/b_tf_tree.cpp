// TfTree::tf(from, to) on a tree of depth 10 with 1,000 frames: cost against path length (should be linear) and
// heap allocations per query (should be exactly one list node per step of the returned chain). Allocations are
// counted by replacing the global operator new in this program.
//
// Baseline row: composing the same path by hand (walking parent pointers, no chain, no allocation).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <random>
#include <vector>

#include "bench_util.h"
#include "rtl/Core.h"
#include "rtl/Transformation.h"

namespace
{
    std::atomic<size_t> g_allocations{0};
}

// Replacing the global operator new/delete pair with malloc/free is valid C++; GCC's -Wmismatched-new-delete cannot
// see that the pair is replaced as a whole and warns where it inlines delete next to a std::allocator's new.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void *operator new(std::size_t size)
{
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void *p = std::malloc(size ? size : 1))
        return p;
    throw std::bad_alloc();
}
void operator delete(void *p) noexcept { std::free(p); }
void operator delete(void *p, std::size_t) noexcept { std::free(p); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace
{
    using Tf = rtl::RigidTf3d;
    using Tree = rtl::TfTree<int, Tf>;
    constexpr int kLevels = 10;
    constexpr int kPerLevel = 100;      // 10 levels x 100 frames = 1,000 frames below the root

    int keyOf(int level, int i) { return level * 1000 + i; }

    //! Hand-composed transformation from `from` to `to` along the tree (the baseline).
    Tf manual(const Tree &tree, int from, int to)
    {
        const Tree::NodeType *a = &tree.at(from), *b = &tree.at(to);
        Tf up = Tf::identity(), down = Tf::identity();
        while (a->depth() > b->depth()) { up.transform(a->tf().inverted()); a = a->parent(); }
        while (b->depth() > a->depth()) { down = b->tf().transformed(down); b = b->parent(); }
        while (a != b)
        {
            up.transform(a->tf().inverted());
            a = a->parent();
            down = b->tf().transformed(down);
            b = b->parent();
        }
        return up.transformed(down);
    }
}

int main(int argc, char **argv)
{
    const auto opt = rtl::bench::parseOptions(argc, argv);
    const int queries = opt.smoke ? 20 : 20000;

    // Build: level L frames hang under random frames of level L-1 (level 0 is the root).
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    auto gen = [&] { return u(rng); };
    Tree tree(0);
    for (int level = 1; level <= kLevels; ++level)
        for (int i = 0; i < kPerLevel; ++i)
        {
            const int parent = level == 1 ? 0 : keyOf(level - 1, std::uniform_int_distribution<int>(0, kPerLevel - 1)(rng));
            tree.insert(keyOf(level, i), Tf::random(gen), parent);
        }
    std::printf("tree: %zu frames, depth %d\n", tree.size(), kLevels);

    // Query sets by path length: up-only queries (level L -> root) have length L; queries between two frames of
    // level L under different root children have length 2L (up to the root, then down).
    struct Case { const char *kind; int length; std::vector<std::pair<int, int>> pairs; };
    std::vector<Case> cases;
    for (int level = 1; level <= kLevels; level += 3)
    {
        Case up{"up", level, {}};
        Case updown{"up+down", 2 * level, {}};
        for (int q = 0; q < queries; ++q)
        {
            const int a = keyOf(level, std::uniform_int_distribution<int>(0, kPerLevel - 1)(rng));
            up.pairs.emplace_back(a, 0);
            // Pick b at the same level with a different level-1 ancestor, so the common ancestor is the root.
            for (;;)
            {
                const int b = keyOf(level, std::uniform_int_distribution<int>(0, kPerLevel - 1)(rng));
                const Tree::NodeType *x = &tree.at(a), *y = &tree.at(b);
                while (x->depth() > 1) { x = x->parent(); y = y->parent(); }
                if (x != y) { updown.pairs.emplace_back(a, b); break; }
            }
        }
        cases.push_back(std::move(up));
        cases.push_back(std::move(updown));
    }

    // Correctness and allocation count (outside the timed loops).
    double worst_diff = 0;
    bool alloc_ok = true;
    std::vector<double> allocs_per_query;
    for (const Case &c : cases)
    {
        size_t allocs = 0;
        for (const auto &p : c.pairs)
        {
            const size_t before = g_allocations.load();
            const auto chain = tree.tf(p.first, p.second);
            allocs += g_allocations.load() - before;
            if (chain.list().size() != static_cast<size_t>(c.length))
                alloc_ok = false;
            const rtl::Vector3d v(0.1, 0.2, 0.3);
            worst_diff = std::max(worst_diff, rtl::Vector3d::distance(chain(v), manual(tree, p.first, p.second)(v)));
        }
        allocs_per_query.push_back(static_cast<double>(allocs) / static_cast<double>(c.pairs.size()));
        if (allocs_per_query.back() != static_cast<double>(c.length))
            alloc_ok = false;
    }

    // Timing: interleaved rounds (every case once per round), medians per case, so that load changes on the shared
    // machine hit all cases alike.
    const size_t kinds = 3;     // hand composition, tf(), tf().squash()
    std::vector<std::vector<double>> times(cases.size() * kinds);
    auto timeOnce = [](auto &&fn) {
        const auto start = std::chrono::steady_clock::now();
        fn();
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    for (int round = -1; round < opt.repetitions; ++round)     // round -1 is an untimed warm-up
        for (size_t ci = 0; ci < cases.size(); ++ci)
        {
            const Case &c = cases[ci];
            const double t_manual = timeOnce([&] {
                for (const auto &p : c.pairs)
                    rtl::bench::doNotOptimize(manual(tree, p.first, p.second));
            });
            const double t_query = timeOnce([&] {
                for (const auto &p : c.pairs)
                {
                    const auto chain = tree.tf(p.first, p.second);
                    rtl::bench::doNotOptimize(chain.list().size());
                }
            });
            const double t_squash = timeOnce([&] {
                for (const auto &p : c.pairs)
                    rtl::bench::doNotOptimize(tree.tf(p.first, p.second).squash());
            });
            if (round >= 0)
            {
                times[ci * kinds].push_back(t_manual);
                times[ci * kinds + 1].push_back(t_query);
                times[ci * kinds + 2].push_back(t_squash);
            }
        }
    auto median = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
        return v[v.size() / 2];
    };

    rtl::bench::printHeader("TfTree<int, RigidTf3d>::tf(from, to), 1,000 frames, depth 10 (baseline: hand composition)");
    std::vector<std::pair<double, double>> length_ns;     // (path length, ns per tf() query)
    for (size_t ci = 0; ci < cases.size(); ++ci)
    {
        const Case &c = cases[ci];
        const double t_manual = median(times[ci * kinds]), t_query = median(times[ci * kinds + 1]),
                     t_squash = median(times[ci * kinds + 2]);
        const double per_query = t_query / static_cast<double>(c.pairs.size());
        const double ns_step = per_query * 1e9 / c.length;
        length_ns.emplace_back(c.length, per_query * 1e9);
        char name[64], note[128];
        std::snprintf(name, sizeof name, "%s, path length %d: hand composition", c.kind, c.length);
        rtl::bench::printRow(name, c.pairs.size(), t_manual, t_manual);
        std::snprintf(name, sizeof name, "%s, path length %d: tf()", c.kind, c.length);
        std::snprintf(note, sizeof note, "%.0f ns/query, %.1f ns/step, %.2f allocs/query", per_query * 1e9, ns_step,
                      allocs_per_query[ci]);
        rtl::bench::printRow(name, c.pairs.size(), t_query, t_manual, note);
        std::snprintf(name, sizeof name, "%s, path length %d: tf().squash()", c.kind, c.length);
        rtl::bench::printRow(name, c.pairs.size(), t_squash, t_manual);
    }
    // Least-squares line ns = a + b * length; linear cost means small residuals relative to the fitted values.
    double sl = 0, st = 0, sll = 0, slt = 0;
    const double m = static_cast<double>(length_ns.size());
    for (const auto &[l, t] : length_ns)
    {
        sl += l; st += t; sll += l * l; slt += l * t;
    }
    const double b = (m * slt - sl * st) / (m * sll - sl * sl), a = (st - b * sl) / m;
    double worst_rel = 0;
    for (const auto &[l, t] : length_ns)
        worst_rel = std::max(worst_rel, std::abs(t - (a + b * l)) / (a + b * l));
    std::printf("tf() query cost fit: %.0f ns + %.1f ns x path length; largest deviation from the line %.0f%%\n", a, b,
                100 * worst_rel);
    std::printf("max |chain(v) - hand(v)| = %.2e; allocations per query == path length: %s\n", worst_diff,
                alloc_ok ? "yes" : "NO");
    return (worst_diff < 1e-9 && alloc_ok) ? 0 : 1;
}
