#include "oracle/ray_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

namespace hexray::oracle {
namespace {

LightStatus truthStatus(const LightTruth& light) {
    if (light.atPoint)
        return LightStatus::AtPoint;
    if (!light.facing)
        return LightStatus::FacingAway;
    return light.blocked ? LightStatus::Shadowed : LightStatus::Lit;
}

const char* statusName(LightStatus status) {
    switch (status) {
        case LightStatus::Lit:
            return "lit";
        case LightStatus::FacingAway:
            return "facing away";
        case LightStatus::Shadowed:
            return "shadowed";
        default:
            return "at point";
    }
}

std::string describeNode(const std::optional<std::size_t>& node) {
    return node ? "node " + std::to_string(*node) : "background";
}

class Checker {
public:
    Checker(const Judged& judged, const RendererRay& rendered, const std::string& label, Tally& tally)
        : judged_(judged), truth_(judged.truth), rendered_(rendered), label_(label), tally_(tally) {}

    void run() {
        ++tally_.rays;
        if (!decide(judged_.nodeConditioning, rendered_.node == truth_.node,
                    "shows " + describeNode(rendered_.node) + ", exactly " + describeNode(truth_.node))) {
            return;  // nothing after the hit is comparable
        }
        if (judged_.nodeConditioning < kWellConditioned || !truth_.node) {
            return;
        }
        checkDistance();
        checkNormal();
        if (truth_.oddChecker) {
            decide(judged_.checkerConditioning, rendered_.oddChecker == *truth_.oddChecker,
                   std::string("checker cell ") + (rendered_.oddChecker ? "odd" : "even") + ", exactly " +
                       (*truth_.oddChecker ? "odd" : "even"));
        }
        for (std::size_t i = 0; i < truth_.lights.size() && i < rendered_.lights.size(); ++i) {
            checkLight(i);
        }
    }

private:
    // Counts a well-conditioned decision; returns false when it was judged wrong.
    bool decide(double conditioning, bool right, const std::string& what) {
        if (conditioning < kWellConditioned) {
            return true;
        }
        ++tally_.decisions;
        tally_.rightDecisions += right ? 1 : 0;
        if (!right) {
            fail(what + " (conditioning " + format(conditioning) + " units of roundoff)");
        }
        return right;
    }

    void checkDistance() {
        const double ulp = ulpAt(truth_.scale, judged_.unitRoundoff);
        if (judged_.tSensitivity > kValueSensitivity * ulp) {
            return;
        }
        const double ulps = std::abs(rendered_.t - truth_.t) / ulp;
        ++tally_.distances;
        tally_.maxDistanceUlps = std::max(tally_.maxDistanceUlps, ulps);
        if (!(ulps <= kDistanceUlps)) {
            fail("t = " + format(rendered_.t) + ", exactly " + format(truth_.t) + ": " + format(ulps) +
                 " ulps of the scale " + format(truth_.scale));
        }
    }

    double u() const { return judged_.unitRoundoff; }

    double normalUnit() const { return truth_.radius > 0 ? u() * std::max(1.0, truth_.scale / truth_.radius) : u(); }

    void checkNormal() {
        const glm::dvec3 error = glm::abs(rendered_.normal - truth_.normal);
        checkValue(std::max({error.x, error.y, error.z}), judged_.normalSensitivity, normalUnit(), "normal");
    }

    void checkLight(std::size_t i) {
        const LightTruth& light = truth_.lights[i];
        const RendererRay::Light& seen = rendered_.lights[i];
        const std::string name = "light " + std::to_string(i) + ": ";
        if (!decide(judged_.lightConditioning[i], seen.status == truthStatus(light),
                    name + statusName(seen.status) + ", exactly " + statusName(truthStatus(light))) ||
            judged_.lightConditioning[i] < kWellConditioned || light.atPoint) {
            return;
        }
        const double distance = std::sqrt(light.distanceSquared);
        double pointScale = std::max(truth_.scale, truth_.t);
        if (rendered_.worldCoordinates) {
            pointScale = std::max({pointScale, glm::length(rendered_.origin), glm::length(truth_.point)});
        }
        const double pointError = u() * pointScale / distance;
        checkValue(std::abs(seen.cosTheta - light.cosTheta), judged_.cosSensitivity[i], normalUnit() + pointError,
                   name + "cos theta " + format(seen.cosTheta) + ", exactly " + format(light.cosTheta));
        checkValue(std::abs(seen.distanceSquared / light.distanceSquared - 1.0),
                   judged_.distanceSquaredSensitivity[i] / light.distanceSquared, 2.0 * pointError + 4.0 * u(),
                   name + "r^2 " + format(seen.distanceSquared) + ", exactly " + format(light.distanceSquared));
    }

    // A value judged where well conditioned (sensitivity within kValueSensitivity units).
    void checkValue(double error, double sensitivity, double unit, const std::string& what) {
        if (sensitivity > kValueSensitivity * unit) {
            return;
        }
        ++tally_.values;
        tally_.maxValueUnits = std::max(tally_.maxValueUnits, error / unit);
        if (!(error <= kValueBound * unit)) {
            fail(what + ": off by " + format(error / unit) + " units of " + format(unit));
        }
    }

    void fail(const std::string& what) {
        char ray[200];
        std::snprintf(ray, sizeof ray, " [ray (%.17g, %.17g, %.17g) + t (%.17g, %.17g, %.17g)]", rendered_.origin.x,
                      rendered_.origin.y, rendered_.origin.z, rendered_.direction.x, rendered_.direction.y,
                      rendered_.direction.z);
        tally_.failures.push_back(label_ + ": " + what + ray);
    }

    static std::string format(double value) {
        char text[32];
        std::snprintf(text, sizeof text, "%.10g", value);
        return text;
    }

    const Judged& judged_;
    const RayTruth& truth_;
    const RendererRay& rendered_;
    const std::string& label_;
    Tally& tally_;
};

}  // namespace

void Tally::add(const Tally& other) {
    rays += other.rays;
    decisions += other.decisions;
    rightDecisions += other.rightDecisions;
    distances += other.distances;
    maxDistanceUlps = std::max(maxDistanceUlps, other.maxDistanceUlps);
    values += other.values;
    maxValueUnits = std::max(maxValueUnits, other.maxValueUnits);
    failures.insert(failures.end(), other.failures.begin(), other.failures.end());
}

void checkRay(const Judged& judged, const RendererRay& rendered, const std::string& label, Tally& tally) {
    Checker(judged, rendered, label, tally).run();
}

double ulpAt(double x, double unitRoundoff) {
    return 2.0 * unitRoundoff * std::exp2(std::floor(std::log2(std::abs(x))));
}

}  // namespace hexray::oracle
