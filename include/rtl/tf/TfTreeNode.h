// TfTreeNode: one frame of a TfTree. It stores its key, the transformation from its parent's frame to its own
// (tf()), a pointer to its parent and the set of its children
// (docs/reference.md, "TfTreeNode").
//
// Linking rules: a root (key constructor) is its own parent; a default-constructed node has no parent. A node built
// with a parent registers itself in the parent's child set. Destroying a linked node unregisters it from its parent and
// orphans its children (their parent() becomes nullptr), so no pointer is left dangling whatever the destruction
// order. Moving a node relinks the parent and the children to the new address. A copy is a detached snapshot: it
// shows the same parent pointer and child set but takes part in no links, so destroying it (even after the tree is
// gone) touches nothing.
//
// Complexity: linking and unlinking a child O(log c) for c children (a std::set of pointers, so children are
// listed in address order); a move relinks the parent and every child, O(c log c).
#pragma once

#include <cstddef>
#include <set>
#include <utility>

namespace rtl
{
    template<typename, typename> class TfTree;

    template<typename K, typename T>
    class TfTreeNode
    {
    public:
        friend class TfTree<K, T>;
        using KeyType = K;
        using TransformationType = T;

        //! Depth 0, no parent, default key and transformation.
        TfTreeNode() = default;

        //! Member-wise snapshot (same key, transformation, parent pointer, child set and depth), not registered.
        TfTreeNode(const TfTreeNode &cp)
                : int_key(cp.int_key), int_tf(cp.int_tf), int_parent(cp.int_parent), int_children(cp.int_children),
                  int_depth(cp.int_depth), linked(false) {}

        //! Takes over mv's place in the tree: the parent's child set and the children's parent pointers are relinked to
        //! this node; a root becomes its own parent. mv is left detached (no parent, no children).
        TfTreeNode(TfTreeNode &&mv) noexcept
                : int_key(std::move(mv.int_key)), int_tf(std::move(mv.int_tf)), int_parent(mv.int_parent),
                  int_children(std::move(mv.int_children)), int_depth(mv.int_depth), linked(mv.linked)
        {
            if (int_parent == &mv)
                int_parent = this;
            else if (linked && int_parent != nullptr)
            {
                int_parent->int_children.erase(&mv);
                int_parent->int_children.insert(this);
            }
            if (linked)
                for (TfTreeNode *child : int_children)
                    child->int_parent = this;
            mv.int_parent = nullptr;
            mv.int_children.clear();
            mv.linked = false;
        }

        //! A root node: depth 0 and its own parent.
        explicit TfTreeNode(const KeyType &key) : int_key(key), int_parent(this) {}

        //! A child of `parent`, reached from the parent's frame by `transformation`; registers in the parent's children.
        template<typename Tf>
        TfTreeNode(const KeyType &key, Tf &&transformation, TfTreeNode<K, T> &parent)
                : int_key(key), int_tf(std::forward<Tf>(transformation)), int_parent(&parent), int_depth(parent.int_depth + 1)
        {
            parent.int_children.insert(this);
        }

        //! A linked node removes itself from its parent's child set and orphans its children.
        ~TfTreeNode()
        {
            if (!linked)
                return;
            if (int_parent != nullptr && int_parent != this)
                int_parent->int_children.erase(this);
            for (TfTreeNode *child : int_children)
                child->int_parent = nullptr;
        }

        TfTreeNode &operator=(const TfTreeNode &) = delete;
        TfTreeNode &operator=(TfTreeNode &&) = delete;

        [[nodiscard]] const KeyType &key() const { return int_key; }
        [[nodiscard]] TfTreeNode *parent() const { return int_parent; }
        [[nodiscard]] const auto &children() const { return int_children; }
        [[nodiscard]] size_t depth() const { return int_depth; }
        //! Transformation from the parent's frame to this node's frame.
        [[nodiscard]] const TransformationType &tf() const { return int_tf; }
        [[nodiscard]] TransformationType &tf() { return int_tf; }

    private:
        KeyType int_key{};
        TransformationType int_tf{};
        TfTreeNode *int_parent = nullptr;
        std::set<TfTreeNode *> int_children;
        size_t int_depth = 0;
        bool linked = true;    // takes part in the parent/child links (false for snapshots and moved-from nodes)
    };
}
