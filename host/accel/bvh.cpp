#include "accel/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <variant>

#include <glm/common.hpp>

namespace hexray {

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

struct Item {
    std::uint32_t sceneNode = 0;
    Box box;
    glm::dvec3 centre{0.0};
};

class Builder {
public:
    explicit Builder(std::vector<Item> items) : items_(std::move(items)) {}

    Bvh build() {
        if (!items_.empty()) {
            buildNode(0, static_cast<std::uint32_t>(items_.size()));
        }
        bvh_.sphereNodes.reserve(items_.size());
        for (const Item& item : items_) {
            bvh_.sphereNodes.push_back(item.sceneNode);
        }
        return std::move(bvh_);
    }

private:
    // Builds the subtree over items_[first, first + count) and returns its node index.
    std::uint32_t buildNode(std::uint32_t first, std::uint32_t count) {
        const auto nodeIndex = static_cast<std::uint32_t>(bvh_.nodes.size());
        bvh_.nodes.emplace_back();
        Box bounds;
        Box centres;
        for (std::uint32_t i = first; i < first + count; ++i) {
            bounds.grow(items_[i].box);
            centres.grow(items_[i].centre);
        }
        bvh_.nodes[nodeIndex].boundsMin = bounds.min;
        bvh_.nodes[nodeIndex].boundsMax = bounds.max;
        if (count <= kMaxBvhLeafSpheres) {
            bvh_.nodes[nodeIndex].firstOrSecondChild = first;
            bvh_.nodes[nodeIndex].count = count;
            return nodeIndex;
        }

        const std::uint32_t leftCount = partition(first, count, centres);
        buildNode(first, leftCount);
        const std::uint32_t second = buildNode(first + leftCount, count - leftCount);
        bvh_.nodes[nodeIndex].firstOrSecondChild = second;
        bvh_.nodes[nodeIndex].count = 0;
        return nodeIndex;
    }

    // Reorders items_[first, first + count) into two non-empty groups; returns the first's size.
    // Binned SAH along the axis where the centres spread most; when every centre falls in one
    // bin (identical centres), a split of the list in half, in scene order.
    std::uint32_t partition(std::uint32_t first, std::uint32_t count, const Box& centres) {
        const glm::dvec3 extent = centres.max - centres.min;
        int axis = 0;
        if (extent.y > extent[axis]) axis = 1;
        if (extent.z > extent[axis]) axis = 2;
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
            binBoxes[bin].grow(it->box);
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
        const auto middle = std::stable_partition(begin, end, [&](const Item& item) { return binOf(item) < bestSplit; });
        return static_cast<std::uint32_t>(middle - begin);
    }

    std::vector<Item> items_;
    Bvh bvh_;
};

}  // namespace

std::size_t countSpheres(const Scene& scene) {
    return static_cast<std::size_t>(std::count_if(scene.nodes.begin(), scene.nodes.end(), [](const Node& node) {
        return std::holds_alternative<Sphere>(node.geometry);
    }));
}

bool bvhPays(const Scene& scene) {
    return countSpheres(scene) > kBvhMinSpheres;
}

Bvh buildBvh(const Scene& scene) {
    std::vector<Item> items;
    std::vector<std::uint32_t> planeNodes;
    for (std::size_t index = 0; index < scene.nodes.size(); ++index) {
        if (std::holds_alternative<Plane>(scene.nodes[index].geometry)) {
            planeNodes.push_back(static_cast<std::uint32_t>(index));
        }
        if (const auto* sphere = std::get_if<Sphere>(&scene.nodes[index].geometry)) {
            const double r = std::abs(sphere->radius);
            Item item;
            item.sceneNode = static_cast<std::uint32_t>(index);
            item.box.min = sphere->center - r;
            item.box.max = sphere->center + r;
            item.centre = sphere->center;
            items.push_back(item);
        }
    }
    Bvh bvh = Builder(std::move(items)).build();
    bvh.planeNodes = std::move(planeNodes);
    return bvh;
}

}  // namespace hexray
