#include "oracle/oracle.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "oracle/exact.h"

namespace hexray::oracle {
namespace {

ExactVec exact(const glm::dvec3& v) {
    return {v.x, v.y, v.z};
}

glm::dvec3 rounded(const ExactVec& v) {
    return {v.x.toDouble(), v.y.toDouble(), v.z.toDouble()};
}

// A ray with a unit direction, and one node's candidate along it.
struct ExactRay {
    ExactVec origin;
    ExactVec direction;
};

// The scene's geometry and lights as exact numbers: as given, or as a renderer holds them at its
// precision (eye-relative offsets rounded, see placed()).
struct ExactNode {
    bool plane = false;
    Exact height;
    ExactVec center;
    Exact radius;
};
struct ExactScene {
    std::vector<ExactNode> nodes;
    std::vector<ExactVec> lights;
};

ExactScene asGiven(const Scene& scene) {
    ExactScene result;
    for (const Node& node : scene.nodes) {
        if (const auto* plane = std::get_if<Plane>(&node.geometry)) {
            result.nodes.push_back({true, plane->height, {}, 0.0});
        } else {
            const Sphere& sphere = std::get<Sphere>(node.geometry);
            result.nodes.push_back({false, 0.0, exact(sphere.center), sphere.radius});
        }
    }
    for (const PointLight& light : scene.lights)
        result.lights.push_back(exact(light.position));
    return result;
}

// x rounded to the precision whose unit roundoff is u (float or double).
Exact roundedTo(const Exact& x, double unitRoundoff) {
    const double asDouble = x.toDouble();
    return unitRoundoff > 0x1p-30 ? Exact(double(float(asDouble))) : Exact(asDouble);
}

ExactVec roundedTo(const ExactVec& v, double unitRoundoff) {
    return {roundedTo(v.x, unitRoundoff), roundedTo(v.y, unitRoundoff), roundedTo(v.z, unitRoundoff)};
}

// Every position as the origin plus its offset from it rounded to the precision, every radius
// rounded: what a renderer working relative to the eye at that precision can hold.
ExactScene placed(const ExactScene& scene, const ExactVec& origin, double unitRoundoff) {
    ExactScene result = scene;
    for (ExactNode& node : result.nodes) {
        node.height = origin.y + roundedTo(node.height - origin.y, unitRoundoff);
        node.center = origin + roundedTo(node.center - origin, unitRoundoff);
        node.radius = roundedTo(node.radius, unitRoundoff);
    }
    for (ExactVec& light : result.lights)
        light = origin + roundedTo(light - origin, unitRoundoff);
    return result;
}

struct Candidate {
    bool hit = false;
    Exact t;
    Exact margin;                 // > 0 hit, < 0 miss
    bool infiniteMargin = false;  // no direction flips it (origin inside a sphere, or on a plane)
};

// A sphere: roots of |f + t d|^2 = r^2 for f = o - c, b = f.d, power = |f|^2 - r^2. The
// near root comes as power / q, so a ray starting exactly on the sphere has it exactly 0.
Candidate sphereCandidate(const ExactRay& ray, const ExactNode& sphere) {
    const ExactVec f = ray.origin - sphere.center;
    const Exact& r = sphere.radius;
    const Exact b = dot(f, ray.direction);
    const Exact power = dot(f, f) - r * r;
    const Exact lineDistance = length(f - b * ray.direction);
    Candidate c;
    if (power.sign() < 0) {
        c.infiniteMargin = true;  // inside: the far root, whatever the direction
        c.margin = 1.0;
    } else if (power.isZero()) {
        c.margin = -b;  // on the surface: a hit exactly when heading inward
    } else {
        // Outside: a hit when the line passes within r and the centre is ahead. With the centre
        // behind, |l| > r near b = 0, so r - |f| continues r - |l| across it.
        c.margin = b.sign() < 0 ? r - lineDistance : r - sqrt(dot(f, f));
    }
    const Exact discriminant = b * b - power;
    if (discriminant.sign() < 0) {
        return c;
    }
    const Exact root = sqrt(discriminant);
    const Exact q = b.sign() >= 0 ? -b - root : -b + root;
    if (q.isZero()) {
        return c;
    }
    const Exact near = min(power / q, q);
    const Exact far = max(power / q, q);
    c.hit = c.margin.sign() > 0 || c.infiniteMargin;
    c.t = near.sign() > 0 ? near : far;
    c.hit = c.hit && c.t.sign() > 0;
    return c;
}

// The plane y = h: a hit when the ray heads toward it from off it.
Candidate planeCandidate(const ExactRay& ray, const ExactNode& plane) {
    const Exact above = ray.origin.y - plane.height;
    Candidate c;
    if (above.isZero()) {
        c.infiniteMargin = true;  // on the plane: t = 0 is not a hit, whatever the direction
        c.margin = -1.0;
        return c;
    }
    c.margin = above.sign() > 0 ? -ray.direction.y : ray.direction.y;
    c.hit = c.margin.sign() > 0;
    if (c.hit) {
        c.t = -above / ray.direction.y;
    }
    return c;
}

Candidate candidate(const ExactRay& ray, const ExactNode& node) {
    return node.plane ? planeCandidate(ray, node) : sphereCandidate(ray, node);
}

// Distance along the open segment from `from` (length `span`, unit `toward`) to the nearest
// boundary of "node crosses the segment"; `onSurface`: `from` lies on this node (the hit itself).
struct Blocking {
    bool blocked = false;
    Exact margin;
    bool infiniteMargin = false;
};

Blocking sphereBlocking(const ExactVec& from, const ExactVec& toward, const Exact& span, const ExactNode& sphere,
                        bool onSurface) {
    const ExactVec f = from - sphere.center;
    const Exact& r = sphere.radius;
    const Exact b = dot(f, toward);
    Blocking result;
    if (onSurface) {
        // The other root of a segment leaving the surface is -2b.
        const Exact other = Exact(-2.0) * b;
        result.blocked = other.sign() > 0 && other < span;
        result.margin = min(abs(other), abs(span - other));
        return result;
    }
    const Exact power = dot(f, f) - r * r;
    const Exact discriminant = b * b - power;
    // The tangent boundary counts where the closest point lies on the segment.
    const Exact closest = -b;
    const Exact lineGap = abs(length(f - b * toward) - r);
    result.margin = closest.sign() > 0 && closest < span ? lineGap : Exact(kUnbounded);
    if (discriminant.sign() < 0) {
        return result;
    }
    const Exact root = sqrt(discriminant);
    for (const Exact& s : {-b - root, -b + root}) {
        result.blocked = result.blocked || (s.sign() > 0 && s < span);
        result.margin = min(result.margin, min(abs(s), abs(span - s)));
    }
    return result;
}

Blocking planeBlocking(const ExactVec& from, const ExactVec& to, const ExactNode& plane, bool onSurface) {
    Blocking result;
    if (onSurface) {
        result.infiniteMargin = true;  // the segment leaves its own plane at t = 0
        return result;
    }
    const Exact fromSide = from.y - plane.height;
    const Exact toSide = to.y - plane.height;
    result.blocked = fromSide.sign() * toSide.sign() < 0;
    result.margin = min(abs(fromSide), abs(toSide));
    return result;
}

LightTruth lightTruth(const ExactScene& scene, std::size_t hitNode, const ExactVec& point, const ExactVec& normal,
                      const ExactVec& light) {
    LightTruth truth;
    const ExactVec toLight = light - point;
    const Exact distanceSquared = dot(toLight, toLight);
    truth.distanceSquared = distanceSquared.toDouble();
    if (distanceSquared.isZero()) {
        truth.atPoint = true;
        return truth;
    }
    const Exact distance = sqrt(distanceSquared);
    const Exact cosTheta = dot(normal, toLight) / distance;
    truth.cosTheta = truth.facingMargin = cosTheta.toDouble();
    truth.facing = cosTheta.sign() > 0;
    if (!truth.facing) {
        return truth;
    }
    const ExactVec toward = (Exact(1.0) / distance) * toLight;
    Exact margin = kUnbounded;
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        const ExactNode& node = scene.nodes[i];
        const Blocking blocking = node.plane ? planeBlocking(point, light, node, i == hitNode)
                                             : sphereBlocking(point, toward, distance, node, i == hitNode);
        truth.blocked = truth.blocked || blocking.blocked;
        if (!blocking.infiniteMargin) {
            margin = min(margin, blocking.margin);
        }
    }
    truth.blockMargin = margin.toDouble();
    return truth;
}

// The distance to the nearest integer of x / size, times size: how far x is from a cell edge.
Exact edgeDistance(const Exact& x, double size) {
    const Exact cells = x / Exact(size);
    const Exact fraction = cells - floor(cells);
    return Exact(size) * min(fraction, Exact(1.0) - fraction);
}

void setChecker(RayTruth& truth, bool plane, const ExactVec& point, const ExactVec& outward, double size) {
    Exact u;
    Exact v;
    Exact margin = kUnbounded;
    if (plane) {
        u = point.x;
        v = point.z;
    } else {
        // Longitude and latitude in degrees of the outward normal; the longitude's cut at +-180
        // is an edge too.
        const Exact degrees = Exact(180.0) / Exact::pi();
        u = degrees * atan2(outward.x, outward.z);
        v = degrees * atan2(outward.y, sqrt(outward.x * outward.x + outward.z * outward.z));
        margin = Exact(180.0) - abs(u);
    }
    truth.oddChecker = isOdd(floor(u / Exact(size))) != isOdd(floor(v / Exact(size)));
    truth.checkerMargin = min(margin, min(edgeDistance(u, size), edgeDistance(v, size))).toDouble();
}

// The magnitude a hit's arithmetic works at, for distances in ulps: a sphere's max(|o - c|, r),
// a plane's t (its hit point is o + t d).
double distanceScale(const ExactRay& ray, const ExactNode& node, const Exact& t) {
    if (node.plane) {
        return t.toDouble();
    }
    return max(length(ray.origin - node.center), node.radius).toDouble();
}

RayTruth traceExact(const Scene& scene, const ExactScene& geometry, const ExactRay& ray) {
    RayTruth truth;
    std::vector<Candidate> candidates;
    for (const ExactNode& node : geometry.nodes) {
        candidates.push_back(candidate(ray, node));
        truth.hitMargins.push_back(candidates.back().infiniteMargin
                                       ? std::copysign(kUnbounded, candidates.back().margin.toDouble())
                                       : candidates.back().margin.toDouble());
    }
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (candidates[i].hit && (!truth.node || candidates[i].t < candidates[*truth.node].t)) {
            truth.node = i;
        }
    }
    if (!truth.node) {
        return truth;
    }
    const std::size_t hit = *truth.node;
    const Exact& t = candidates[hit].t;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (i != hit && candidates[i].hit) {
            truth.nearestGap = std::min(truth.nearestGap, (candidates[i].t - t).toDouble());
        }
    }
    const ExactNode& node = geometry.nodes[hit];
    const ExactVec point = ray.origin + t * ray.direction;
    ExactVec outward;
    if (node.plane) {
        outward = {0.0, 1.0, 0.0};
    } else {
        outward = (Exact(1.0) / node.radius) * (point - node.center);
        truth.radius = node.radius.toDouble();
    }
    const bool flip = node.plane ? ray.direction.y.sign() > 0 : dot(outward, ray.direction).sign() > 0;
    const ExactVec normal = flip ? -outward : outward;
    truth.t = t.toDouble();
    truth.point = rounded(point);
    truth.normal = rounded(normal);
    truth.scale = distanceScale(ray, node, t);
    const Shader& shader = scene.shaders.at(scene.nodes[hit].shaderIndex);
    if (const auto* checker = std::get_if<CheckerShader>(&shader)) {
        setChecker(truth, node.plane, point, outward, checker->size);
    }
    if (!std::holds_alternative<ConstantShader>(shader)) {
        for (const ExactVec& light : geometry.lights) {
            truth.lights.push_back(lightTruth(geometry, hit, point, normal, light));
        }
    }
    return truth;
}

RayTruth traceExact(const Scene& scene, const ExactScene& geometry, const glm::dvec3& origin,
                    const ExactVec& direction) {
    return traceExact(scene, geometry, ExactRay{exact(origin), (Exact(1.0) / length(direction)) * direction});
}

// Root sum of squares of the moves, and the conditioning |margin| / that.
class Sensitivity {
public:
    void add(double base, double moved) {
        const double move = moved - base;
        sumOfSquares_ += std::isfinite(move) ? move * move : (base == moved ? 0.0 : kUnbounded);
    }
    double value() const { return std::sqrt(sumOfSquares_); }
    static double conditioning(double margin, double sensitivity) {
        if (std::isinf(margin))
            return kUnbounded;
        return sensitivity > 0 ? std::abs(margin) / sensitivity : (margin != 0 ? kUnbounded : 0.0);
    }

private:
    double sumOfSquares_ = 0;
};

}  // namespace

RayTruth trace(const Scene& scene, const glm::dvec3& origin, const glm::dvec3& direction) {
    return traceExact(scene, asGiven(scene), origin, exact(direction));
}

Judged judge(const Scene& scene, const glm::dvec3& origin, const glm::dvec3& direction, double unitRoundoff) {
    Judged judged;
    judged.unitRoundoff = unitRoundoff;
    judged.truth = trace(scene, origin, direction);
    const RayTruth& base = judged.truth;
    const std::size_t nodes = scene.nodes.size();
    const std::size_t lights = base.lights.size();

    std::vector<Sensitivity> hit(nodes), cosine(lights), distanceSquared(lights), facing(lights), blocking(lights);
    Sensitivity gap, t, normal, checker;
    bool sameNode = true;
    const ExactScene given = asGiven(scene);
    for (int move = 0; move < 4; ++move) {
        // Moves 0 to 2: the direction by u along one axis; 3: the scene as held at this precision.
        ExactVec perturbed = exact(direction);
        if (move < 3) {
            Exact& component = move == 0 ? perturbed.x : move == 1 ? perturbed.y : perturbed.z;
            component = component + Exact(unitRoundoff);
        }
        const RayTruth moved =
            traceExact(scene, move < 3 ? given : placed(given, exact(origin), unitRoundoff), origin, perturbed);
        for (std::size_t i = 0; i < nodes; ++i)
            hit[i].add(base.hitMargins[i], moved.hitMargins[i]);
        sameNode = sameNode && moved.node == base.node;
        if (!sameNode || !base.node)
            continue;
        gap.add(base.nearestGap, moved.nearestGap);
        t.add(base.t, moved.t);
        for (int c = 0; c < 3; ++c)
            normal.add(base.normal[c], moved.normal[c]);
        checker.add(base.checkerMargin, moved.checkerMargin);
        for (std::size_t i = 0; i < lights; ++i) {
            cosine[i].add(base.lights[i].cosTheta, moved.lights[i].cosTheta);
            distanceSquared[i].add(base.lights[i].distanceSquared, moved.lights[i].distanceSquared);
            facing[i].add(base.lights[i].facingMargin, moved.lights[i].facingMargin);
            blocking[i].add(base.lights[i].blockMargin, moved.lights[i].blockMargin);
        }
    }

    for (std::size_t i = 0; i < nodes; ++i) {
        judged.nodeConditioning =
            std::min(judged.nodeConditioning, Sensitivity::conditioning(base.hitMargins[i], hit[i].value()));
    }
    if (!base.node)
        return judged;
    if (!sameNode) {
        judged.nodeConditioning = 0.0;
    }
    const double downstream = sameNode ? kUnbounded : 0.0;
    judged.nodeConditioning =
        std::min(judged.nodeConditioning, Sensitivity::conditioning(base.nearestGap, gap.value()));
    judged.checkerConditioning = std::min(downstream, Sensitivity::conditioning(base.checkerMargin, checker.value()));
    judged.tSensitivity = sameNode ? t.value() : kUnbounded;
    judged.normalSensitivity = sameNode ? normal.value() : kUnbounded;
    for (std::size_t i = 0; i < lights; ++i) {
        const LightTruth& light = base.lights[i];
        double conditioning = std::min(downstream, Sensitivity::conditioning(light.facingMargin, facing[i].value()));
        if (light.facing) {
            conditioning = std::min(conditioning, Sensitivity::conditioning(light.blockMargin, blocking[i].value()));
        }
        judged.lightConditioning.push_back(light.atPoint ? 0.0 : conditioning);
        judged.cosSensitivity.push_back(sameNode ? cosine[i].value() : kUnbounded);
        judged.distanceSquaredSensitivity.push_back(sameNode ? distanceSquared[i].value() : kUnbounded);
    }
    return judged;
}

}  // namespace hexray::oracle
