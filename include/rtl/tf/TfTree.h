// TfTree: a tree of coordinate frames keyed by K, with the transformation T from each frame's parent to the frame
// stored on the child node (docs/reference.md, "TfTree"). tf(from, to) returns the TfChain mapping coordinates in
// `from` to `to`.
//
// Nodes live in a std::map<K, TfTreeNode> (node-based, so addresses are stable and parent/child pointers stay valid
// across inserts and erases). K must be ordered by operator<. The root always exists.
//
// Complexity (n frames): at, contains, operator[] and insert O(log n); erase O(s log n) for a subtree of s frames;
// tf(from, to) linear in the path length, allocating one list node per step; copies O(n log n), moves O(1) (a
// moved-from tree keeps a root, so it stays usable and destructible).
#pragma once

#include <cstddef>
#include <list>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "rtl/tf/TfTreeNode.h"
#include "rtl/tf/TfChain.h"
#include "rtl/tf/GeneralTf.h"
#include "rtl/tf/VariantResult.h"

namespace rtl
{
    template<typename K, typename T>
    class TfTree
    {
    public:
        typedef K KeyType;
        typedef T TransformationType;
        typedef TfTreeNode<KeyType, TransformationType> NodeType;

        TfTree() = delete;
        explicit TfTree(const KeyType root_key) : int_root_key(root_key) { addRoot(); }

        //! Independent deep copy: every node is re-created with its parent pointer linked to the new tree's nodes.
        TfTree(const TfTree &cp) : int_root_key(cp.int_root_key)
        {
            addRoot();
            rootNode().int_tf = cp.root().int_tf;
            copyChildren(cp.root(), rootNode());
        }

        //! Takes over mv's nodes (their addresses do not change); mv keeps a fresh root with the same key.
        TfTree(TfTree &&mv) noexcept : int_root_key(mv.int_root_key)
        {
            addRoot();
            int_nodes.swap(mv.int_nodes);
        }

        ~TfTree() { detachAll(); }

        TfTree &operator=(const TfTree &cp)
        {
            if (this != &cp)
            {
                TfTree tmp(cp);
                swap(tmp);
            }
            return *this;
        }

        //! Swaps contents: mv ends up with this tree's former nodes, which is a valid tree.
        TfTree &operator=(TfTree &&mv) noexcept
        {
            if (this != &mv)
                swap(mv);
            return *this;
        }

        //! Always false: a valid tree holds at least its root.
        [[nodiscard]] bool empty() const { return int_nodes.empty(); }
        //! Number of frames, including the root.
        [[nodiscard]] size_t size() const { return int_nodes.size(); }

        //! Removes every frame except the root.
        void clear()
        {
            NodeType &root_node = rootNode();
            for (auto it = int_nodes.begin(); it != int_nodes.end();)
            {
                if (&it->second == &root_node)
                    ++it;
                else
                {
                    it->second.linked = false;      // bulk removal: no per-node unlinking needed
                    it = int_nodes.erase(it);
                }
            }
            root_node.int_children.clear();
        }

        //! Adds frame `key` under `parent`, reached from it by `tf`. Returns false (and changes nothing) if the parent
        //! does not exist or the key is already present.
        template<typename Tf>
        bool insert(const KeyType &key, Tf &&tf, const KeyType &parent)
        {
            auto p = int_nodes.find(parent);
            if (p == int_nodes.end() || int_nodes.count(key) != 0)
                return false;
            int_nodes.emplace(std::piecewise_construct, std::forward_as_tuple(key),
                              std::forward_as_tuple(key, std::forward<Tf>(tf), p->second));
            return true;
        }

        //! Removes frame `key` and its whole subtree. Returns false for the root or an unknown key.
        bool erase(const KeyType &key)
        {
            auto it = int_nodes.find(key);
            if (it == int_nodes.end() || &it->second == &rootNode())
                return false;
            // Pre-order collection; erasing in reverse destroys every child before its parent, so each node can still
            // unregister from a live parent.
            std::vector<NodeType *> order{&it->second};
            for (size_t i = 0; i < order.size(); ++i)
                for (NodeType *child : order[i]->int_children)
                    order.push_back(child);
            for (auto n = order.rbegin(); n != order.rend(); ++n)
                int_nodes.erase(int_nodes.find((*n)->int_key));   // by iterator: the key argument lives in the node
            return true;
        }

        [[nodiscard]] bool contains(const KeyType &key) const { return int_nodes.find(key) != int_nodes.end(); }

        [[nodiscard]] const NodeType &root() const { return int_nodes.at(int_root_key); }

        //! The frame `key`; throws std::out_of_range if it does not exist (never inserts).
        NodeType &operator[](const KeyType &key) { return at(key); }
        NodeType &operator[](KeyType &&key) { return at(key); }
        NodeType &at(const KeyType &key) { return findOrThrow(int_nodes, key); }
        const NodeType &at(const KeyType &key) const { return findOrThrow(int_nodes, key); }

        /*! The chain mapping coordinates in frame `from` to frame `to`: the inverses of the node transformations
         *  walking up from `from` to the lowest common ancestor (excluded), then the node transformations walking down
         *  from the ancestor's child to `to`. Cost is linear in the path length; the only allocations are the
         *  returned chain's list nodes. Throws std::out_of_range for an unknown key. */
        TfChain<TransformationType> tf(const KeyType &from, const KeyType &to) const
        {
            const NodeType *up = &at(from);
            const NodeType *down = &at(to);
            std::list<TransformationType> steps;
            auto downBegin = steps.end();    // the down part is built backwards in front of this position
            while (up->int_depth > down->int_depth)
            {
                steps.push_back(up->int_tf.inverted());
                up = up->int_parent;
            }
            // Until the first down step exists, steps.end() is the insertion point; afterwards, the last inserted one.
            auto pushDown = [&](const NodeType *n) { downBegin = steps.insert(downBegin, n->int_tf); };
            while (down->int_depth > up->int_depth)
            {
                pushDown(down);
                down = down->int_parent;
            }
            while (up != down)
            {
                steps.insert(downBegin, up->int_tf.inverted());
                up = up->int_parent;
                pushDown(down);
                down = down->int_parent;
            }
            return TfChain<TransformationType>(std::move(steps));
        }

    private:
        KeyType int_root_key;
        std::map<KeyType, NodeType> int_nodes;

        void addRoot()
        {
            int_nodes.emplace(std::piecewise_construct, std::forward_as_tuple(int_root_key), std::forward_as_tuple(int_root_key));
        }

        NodeType &rootNode() { return int_nodes.find(int_root_key)->second; }

        template<typename Map>
        static auto &findOrThrow(Map &nodes, const KeyType &key)
        {
            auto it = nodes.find(key);
            if (it == nodes.end())
                throw std::out_of_range("TfTree: unknown frame key");
            return it->second;
        }

        //! Re-creates src's subtree under dst (iteratively: deep trees must not exhaust the stack).
        void copyChildren(const NodeType &src_root, NodeType &dst_root)
        {
            std::vector<std::pair<const NodeType *, NodeType *>> todo{{&src_root, &dst_root}};
            while (!todo.empty())
            {
                auto [src, dst] = todo.back();
                todo.pop_back();
                for (const NodeType *child : src->int_children)
                {
                    auto ins = int_nodes.emplace(std::piecewise_construct, std::forward_as_tuple(child->int_key),
                                                 std::forward_as_tuple(child->int_key, child->int_tf, *dst));
                    todo.emplace_back(child, &ins.first->second);
                }
            }
        }

        //! Unlinks every node, so that destroying the map in any order never touches an already destroyed node.
        void detachAll() noexcept
        {
            for (auto &kv : int_nodes)
                kv.second.linked = false;
        }

        void swap(TfTree &other) noexcept
        {
            std::swap(int_root_key, other.int_root_key);
            int_nodes.swap(other.int_nodes);
        }
    };
}
