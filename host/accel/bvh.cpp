#include "accel/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <system_error>
#include <thread>
#include <utility>
#include <variant>

#include <glm/common.hpp>

namespace hexray::inline accel {

namespace {

constexpr std::uint32_t kBinCount = 16;

struct Box {
    glm::dvec3 min{std::numeric_limits<double>::infinity()};
    glm::dvec3 max{-std::numeric_limits<double>::infinity()};

    void grow(const Box& other) {
        min = glm::min(min, other.min);
        max = glm::max(max, other.max);
    }
    void grow(const glm::dvec3& point) {
        min = glm::min(min, point);
        max = glm::max(max, point);
    }
    bool isEmpty() const { return !(min.x <= max.x); }
    double halfArea() const {
        if (isEmpty()) {
            return 0.0;
        }
        const glm::dvec3 e = max - min;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

// A sphere as the builder sorts it; its box is centre -+ |radius|.
struct Item {
    glm::dvec3 centre{0.0};
    double radius = 0.0;  // |radius|
    std::uint32_t sceneNode = 0;

    Box box() const { return Box{centre - radius, centre + radius}; }
};

// The bounds of the items in a range and of their centres: what a node needs to be split.
struct RangeBounds {
    Box bounds;
    Box centres;
};

// Splits items into the subtrees of the BVH. Every decision depends only on the items of the
// range it is made for, so whichever thread builds a subtree, the tree is the same.
class Splitter {
public:
    explicit Splitter(std::vector<Item>& items) : items_(items) {}

    RangeBounds measure(std::uint32_t first, std::uint32_t count) const {
        RangeBounds range;
        for (std::uint32_t i = first; i < first + count; ++i) {
            range.bounds.grow(items_[i].box());
            range.centres.grow(items_[i].centre);
        }
        return range;
    }

    // Builds the subtree over items_[first, first + count) into `nodes`, in depth-first order,
    // with child indices relative to nodes[0]; returns its root's index.
    std::uint32_t buildSubtree(std::uint32_t first, std::uint32_t count, std::vector<BvhNode>& nodes) {
        const auto nodeIndex = static_cast<std::uint32_t>(nodes.size());
        const RangeBounds range = measure(first, count);
        nodes.push_back(BvhNode{range.bounds.min, range.bounds.max, first, count});
        if (count <= kMaxBvhLeafSpheres) {
            return nodeIndex;
        }
        const std::uint32_t leftCount = partition(first, count, range.centres);
        buildSubtree(first, leftCount, nodes);
        const std::uint32_t second = buildSubtree(first + leftCount, count - leftCount, nodes);
        nodes[nodeIndex].firstOrSecondChild = second;
        nodes[nodeIndex].count = 0;
        return nodeIndex;
    }

    // Reorders items_[first, first + count) into two non-empty groups; returns the first's size.
    // Binned SAH along the axis where the centres spread most; when every centre falls in one
    // bin (identical centres), a split of the list in half, in scene order.
    std::uint32_t partition(std::uint32_t first, std::uint32_t count, const Box& centres) {
        const glm::dvec3 extent = centres.max - centres.min;
        int axis = 0;
        if (extent.y > extent[axis])
            axis = 1;
        if (extent.z > extent[axis])
            axis = 2;
        const auto begin = items_.begin() + first;
        const auto end = begin + count;
        if (!(extent[axis] > 0.0)) {
            return count / 2;
        }

        const double low = centres.min[axis];
        const double binScale = double(kBinCount) / extent[axis];
        const auto binOf = [&](const Item& item) {
            const double position = (item.centre[axis] - low) * binScale;
            return std::min(kBinCount - 1, static_cast<std::uint32_t>(position));
        };
        std::array<Box, kBinCount> binBoxes;
        std::array<std::uint32_t, kBinCount> binCounts{};
        for (auto it = begin; it != end; ++it) {
            const std::uint32_t bin = binOf(*it);
            binBoxes[bin].grow(it->box());
            ++binCounts[bin];
        }

        // Cost of splitting after bin `split`: area(left) * count(left) + area(right) * count(right).
        std::array<double, kBinCount> leftCost{};
        Box leftBox;
        std::uint32_t leftCount = 0;
        for (std::uint32_t bin = 0; bin + 1 < kBinCount; ++bin) {
            leftBox.grow(binBoxes[bin]);
            leftCount += binCounts[bin];
            leftCost[bin] = leftBox.halfArea() * leftCount;
        }
        double bestCost = std::numeric_limits<double>::infinity();
        std::uint32_t bestSplit = kBinCount;
        Box rightBox;
        std::uint32_t rightCount = 0;
        for (std::uint32_t bin = kBinCount - 1; bin > 0; --bin) {
            rightBox.grow(binBoxes[bin]);
            rightCount += binCounts[bin];
            const std::uint32_t splitLeftCount = count - rightCount;
            if (rightCount == 0 || splitLeftCount == 0) {
                continue;
            }
            const double cost = leftCost[bin - 1] + rightBox.halfArea() * rightCount;
            if (cost <= bestCost) {  // ties go to the lower split: deterministic either way
                bestCost = cost;
                bestSplit = bin;
            }
        }
        // The centres span the axis, so the first and last bins are both occupied.
        const auto middle =
            std::stable_partition(begin, end, [&](const Item& item) { return binOf(item) < bestSplit; });
        return static_cast<std::uint32_t>(middle - begin);
    }

private:
    std::vector<Item>& items_;
};

// Subtrees of at most this many spheres are built by one thread from start to end; larger ones
// are split, and their halves go to whichever thread is free.
constexpr std::uint32_t kParallelGrain = 1u << 14;

// A part of the tree as one thread built it: the subtree over items [first, first + count).
// Either all its nodes (indices relative to nodes[0]), or, for a large one, only its root and
// the two parts below.
struct Part {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    std::vector<BvhNode> nodes;
    std::unique_ptr<Part> left;
    std::unique_ptr<Part> right;
};

// The parts waiting for a thread, and how many are not yet built.
class PartQueue {
public:
    void push(Part* part) {
        const std::lock_guard lock(mutex_);
        waiting_.push_back(part);
        ++unfinished_;
        ready_.notify_one();
    }

    // The next part to build; nullptr once every part is built (or a thread failed).
    Part* pop() {
        std::unique_lock lock(mutex_);
        ready_.wait(lock, [&] { return !waiting_.empty() || unfinished_ == 0 || failed_; });
        if (waiting_.empty() || failed_) {
            return nullptr;
        }
        Part* part = waiting_.back();
        waiting_.pop_back();
        return part;
    }

    void finished() {
        const std::lock_guard lock(mutex_);
        if (--unfinished_ == 0) {
            ready_.notify_all();
        }
    }

    void fail(std::exception_ptr error) {
        const std::lock_guard lock(mutex_);
        if (!failed_) {
            failed_ = true;
            error_ = std::move(error);
        }
        ready_.notify_all();
    }

    void rethrowFailure() const {
        if (error_) {
            std::rethrow_exception(error_);
        }
    }

private:
    std::mutex mutex_;
    std::condition_variable ready_;
    std::vector<Part*> waiting_;
    std::size_t unfinished_ = 0;
    bool failed_ = false;
    std::exception_ptr error_;
};

void buildPart(Part& part, Splitter& splitter, PartQueue& queue) {
    if (part.count <= kParallelGrain) {
        splitter.buildSubtree(part.first, part.count, part.nodes);
        return;
    }
    const RangeBounds range = splitter.measure(part.first, part.count);
    part.nodes.push_back(BvhNode{range.bounds.min, range.bounds.max, 0, 0});
    const std::uint32_t leftCount = splitter.partition(part.first, part.count, range.centres);
    part.left = std::make_unique<Part>(Part{part.first, leftCount, {}, nullptr, nullptr});
    part.right = std::make_unique<Part>(Part{part.first + leftCount, part.count - leftCount, {}, nullptr, nullptr});
    queue.push(part.left.get());
    queue.push(part.right.get());
}

// Builds parts until none is left.
void buildParts(Splitter& splitter, PartQueue& queue) {
    try {
        while (Part* part = queue.pop()) {
            buildPart(*part, splitter, queue);
            queue.finished();
        }
    } catch (...) {
        queue.fail(std::current_exception());
    }
}

std::size_t nodeCount(const Part& part) {
    return part.nodes.size() + (part.left ? nodeCount(*part.left) + nodeCount(*part.right) : 0);
}

// Appends `part` to `nodes` in depth-first order, its child indices made absolute.
void appendPart(const Part& part, std::vector<BvhNode>& nodes) {
    const auto offset = static_cast<std::uint32_t>(nodes.size());
    if (!part.left) {
        for (BvhNode node : part.nodes) {
            if (!node.isLeaf()) {
                node.firstOrSecondChild += offset;
            }
            nodes.push_back(node);
        }
        return;
    }
    nodes.push_back(part.nodes.front());
    appendPart(*part.left, nodes);
    nodes[offset].firstOrSecondChild = static_cast<std::uint32_t>(nodes.size());
    appendPart(*part.right, nodes);
}

std::vector<BvhNode> buildNodes(std::vector<Item>& items, unsigned threadCount) {
    std::vector<BvhNode> nodes;
    if (items.empty()) {
        return nodes;
    }
    Splitter splitter(items);
    Part root{0, static_cast<std::uint32_t>(items.size()), {}, nullptr, nullptr};
    PartQueue queue;
    queue.push(&root);
    {
        std::vector<std::jthread> helpers;
        for (unsigned helper = 1; helper < threadCount; ++helper) {
            try {
                helpers.emplace_back([&] { buildParts(splitter, queue); });
            } catch (const std::system_error&) {
                break;  // fewer threads build the same tree
            }
        }
        buildParts(splitter, queue);
    }
    queue.rethrowFailure();
    nodes.reserve(nodeCount(root));
    appendPart(root, nodes);
    return nodes;
}

}  // namespace

bool bvhPays(const Scene& scene) {
    return countSpheres(scene) > kBvhMinSpheres;
}

Bvh buildBvh(const Scene& scene, unsigned threadCount) {
    Bvh bvh;
    std::vector<Item> items;
    for (std::size_t index = 0; index < scene.nodes.size(); ++index) {
        if (std::holds_alternative<Plane>(scene.nodes[index].geometry)) {
            bvh.planeNodes.push_back(static_cast<std::uint32_t>(index));
        }
        if (const auto* sphere = std::get_if<Sphere>(&scene.nodes[index].geometry)) {
            items.push_back(Item{sphere->center, std::abs(sphere->radius), static_cast<std::uint32_t>(index)});
        }
    }
    bvh.nodes = buildNodes(items, threadCount ? threadCount : std::max(1u, std::thread::hardware_concurrency()));
    bvh.sphereNodes.reserve(items.size());
    for (const Item& item : items) {
        bvh.sphereNodes.push_back(item.sceneNode);
    }
    return bvh;
}

}  // namespace hexray::accel
