// Many versions of one list that mostly grows and shrinks at its end (a stack with the odd
// removal deeper down), stored at once: each version is the path from its head node up to the
// root, so the prefix it shares with the version stored before it costs nothing again. The
// replay's keyframes keep their dormant gorges and jump pointers this way (core/log/replay.cpp).
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

namespace flood {

template <class T>
class PrefixTree {
public:
    static constexpr uint32_t kEmpty = UINT32_MAX;  // head of the empty list

    // Stores a version of `size` entries whose first `keep` equal those of the version stored
    // last; entry(i) gives the others. Costs one node per entry not kept. Returns its head.
    template <class Entry>
    uint32_t store(size_t size, size_t keep, Entry entry) {
        last_.resize(std::min({keep, size, last_.size()}));
        for (size_t i = last_.size(); i < size; ++i) {
            nodes_.push_back({entry(i), last_.empty() ? kEmpty : last_.back()});
            last_.push_back(uint32_t(nodes_.size() - 1));
        }
        return last_.empty() ? kEmpty : last_.back();
    }

    // Visits entries from..size-1 of the version of `size` entries with head `head`, as
    // visit(i, entry), last first.
    template <class Visit>
    void load(uint32_t head, size_t size, size_t from, Visit visit) const {
        for (size_t i = size; i-- > from; head = nodes_[head].parent) visit(i, nodes_[head].value);
    }

    // How many first entries two versions share as nodes (equal entries stored twice are not
    // counted). Walks only the entries after that.
    size_t commonPrefix(uint32_t a, size_t sizeA, uint32_t b, size_t sizeB) const {
        for (; sizeA > sizeB; --sizeA) a = nodes_[a].parent;
        for (; sizeB > sizeA; --sizeB) b = nodes_[b].parent;
        for (; a != b; --sizeA) a = nodes_[a].parent, b = nodes_[b].parent;
        return sizeA;
    }

    void finish() {  // no store() follows
        std::vector<uint32_t>().swap(last_);
        nodes_.shrink_to_fit();
    }
    size_t nodeCount() const { return nodes_.size(); }
    size_t bytes() const {
        return nodes_.capacity() * sizeof(Node) + last_.capacity() * sizeof(uint32_t);
    }

private:
    struct Node {
        T value;
        uint32_t parent;
    };
    std::vector<Node> nodes_;
    std::vector<uint32_t> last_;  // nodes of the version stored last, by position
};

}  // namespace flood
