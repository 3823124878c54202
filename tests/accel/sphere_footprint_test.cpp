// A ball's footprint in a view must hold every direction that meets the ball, and, in front of the
// view, be the ball's own outline's box (the candidate lists' cost grows with its slack).

#include <cmath>
#include <optional>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "accel/sphere_footprint.h"
#include "support/random_uniform.h"

namespace hexray {
namespace {

using test::uniform;

// A view looking along +z, its window the tangent square [-size, size]^2.
TangentView squareView(double size) {
    TangentView view;
    view.window = {-size, -size, size, size};
    return view;
}

// Tangent coordinates of `direction` in `view`, if it lies in the window.
std::optional<glm::dvec2> tangent(const TangentView& view, const glm::dvec3& direction) {
    const double forward = glm::dot(direction, view.forward);
    if (forward <= 0) {
        return std::nullopt;
    }
    const glm::dvec2 t(glm::dot(direction, view.right) / forward, glm::dot(direction, view.down) / forward);
    const TangentBox& w = view.window;
    if (t.x < w.u0 || t.x > w.u1 || t.y < w.v0 || t.y > w.v1) {
        return std::nullopt;
    }
    return t;
}

// The box around the tangents of `samples` directions from the origin to points of the ball's
// surface (where the outline lies) that fall in the window; nothing if none does.
std::optional<TangentBox> sampledBox(const TangentView& view, const glm::dvec3& center, double radius, int samples,
                                     std::mt19937_64& engine) {
    std::optional<TangentBox> box;
    for (int i = 0; i < samples; ++i) {
        glm::dvec3 offset;
        do {
            offset = glm::dvec3(uniform(engine, -1, 1), uniform(engine, -1, 1), uniform(engine, -1, 1));
        } while (glm::length(offset) > 1.0 || glm::length(offset) < 0.1);
        const auto t = tangent(view, center + radius * glm::normalize(offset));
        if (!t) {
            continue;
        }
        box = box ? TangentBox{std::min(box->u0, t->x), std::min(box->v0, t->y), std::max(box->u1, t->x),
                               std::max(box->v1, t->y)}
                  : TangentBox{t->x, t->y, t->x, t->y};
    }
    return box;
}

bool holds(const TangentBox& outer, const TangentBox& inner) {
    return outer.u0 <= inner.u0 && outer.v0 <= inner.v0 && inner.u1 <= outer.u1 && inner.v1 <= outer.v1;
}

TEST(SphereFootprint, HoldsEveryDirectionIntoBallsInFrontAcrossAndBehindTheView) {
    std::mt19937_64 engine(5);
    const TangentView view = squareView(1.5);
    int inFront = 0;
    int across = 0;
    for (int ball = 0; ball < 400; ++ball) {
        const glm::dvec3 center(uniform(engine, -8, 8), uniform(engine, -8, 8), uniform(engine, -4, 8));
        const double radius = std::exp(uniform(engine, std::log(0.01), std::log(4.0)));
        if (glm::length(center) <= radius) {
            continue;
        }
        (center.z > radius ? inFront : across) += 1;
        const auto sampled = sampledBox(view, center, radius, 2000, engine);
        const auto footprint = ballFootprint(view, center, radius);
        if (!sampled) {
            continue;
        }
        ASSERT_TRUE(footprint) << "ball " << ball;
        EXPECT_TRUE(holds(*footprint, *sampled)) << "ball " << ball;
    }
    EXPECT_GT(inFront, 100);
    EXPECT_GT(across, 100);
}

TEST(SphereFootprint, IsTheOutlinesBoxForABallInFront) {
    std::mt19937_64 engine(7);
    const TangentView view = squareView(10.0);
    for (int ball = 0; ball < 50; ++ball) {
        const glm::dvec3 center(uniform(engine, -3, 3), uniform(engine, -3, 3), uniform(engine, 4, 10));
        const double radius = uniform(engine, 0.1, 2.0);
        const auto sampled = sampledBox(view, center, radius, 20000, engine);
        const auto footprint = ballFootprint(view, center, radius);
        ASSERT_TRUE(sampled && footprint);
        EXPECT_TRUE(holds(*footprint, *sampled));
        // 20000 samples come within a few thousandths of the outline's extremes.
        const double slack = 0.01 * footprint->width();
        EXPECT_NEAR(footprint->u0, sampled->u0, slack);
        EXPECT_NEAR(footprint->u1, sampled->u1, slack);
        EXPECT_NEAR(footprint->v0, sampled->v0, slack);
        EXPECT_NEAR(footprint->v1, sampled->v1, slack);
    }
}

TEST(SphereFootprint, IsTheWholeWindowFromInsideAndNothingWhereTheBallIsOutOfView) {
    const TangentView view = squareView(1.0);
    const auto inside = ballFootprint(view, {0.5, 0.2, -0.3}, 1.0);
    ASSERT_TRUE(inside);
    EXPECT_EQ(inside->u0, -1.0);
    EXPECT_EQ(inside->v1, 1.0);
    EXPECT_FALSE(ballFootprint(view, {0, 0, -5}, 1.0));    // behind
    EXPECT_FALSE(ballFootprint(view, {10, 0, 3}, 1.0));    // beside the window
    EXPECT_FALSE(ballFootprint(view, {0, 50, 0.5}, 1.0));  // across the plane, far to the side
}

}  // namespace
}  // namespace hexray
