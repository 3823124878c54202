#include "fuzz/scene_shrinker.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "scene/scene_loader.h"
#include "scene/scene_writer.h"

namespace hexray::test {
namespace {

// One number of a scene, found again in any copy of it by the same path.
struct Number {
    std::function<double&(Scene&)> in;
    bool mayBeZero = true;
};

void addTriple(std::vector<Number>& numbers, const std::function<glm::dvec3&(Scene&)>& triple, bool mayBeZero = true) {
    for (int axis = 0; axis < 3; ++axis) {
        numbers.push_back({[=](Scene& s) -> double& { return triple(s)[axis]; }, mayBeZero});
    }
}

// Every number of `scene`, in the order a reader meets them.
std::vector<Number> numbersOf(const Scene& scene) {
    std::vector<Number> numbers;
    addTriple(numbers, [](Scene& s) -> glm::dvec3& { return s.camera.position; });
    numbers.push_back({[](Scene& s) -> double& { return s.camera.yawDegrees; }});
    numbers.push_back({[](Scene& s) -> double& { return s.camera.pitchDegrees; }});
    numbers.push_back({[](Scene& s) -> double& { return s.camera.rollDegrees; }});
    numbers.push_back({[](Scene& s) -> double& { return s.camera.fovDegrees; }, false});
    addTriple(numbers, [](Scene& s) -> glm::dvec3& { return s.background; });
    addTriple(numbers, [](Scene& s) -> glm::dvec3& { return s.ambient; });
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        addTriple(numbers, [=](Scene& s) -> glm::dvec3& { return s.lights[i].position; });
        addTriple(numbers, [=](Scene& s) -> glm::dvec3& { return s.lights[i].color; });
        numbers.push_back({[=](Scene& s) -> double& { return s.lights[i].intensity; }});
    }
    for (std::size_t i = 0; i < scene.shaders.size(); ++i) {
        if (std::holds_alternative<CheckerShader>(scene.shaders[i])) {
            addTriple(numbers, [=](Scene& s) -> glm::dvec3& { return std::get<CheckerShader>(s.shaders[i]).color1; });
            addTriple(numbers, [=](Scene& s) -> glm::dvec3& { return std::get<CheckerShader>(s.shaders[i]).color2; });
            numbers.push_back({[=](Scene& s) -> double& { return std::get<CheckerShader>(s.shaders[i]).size; }, false});
        } else if (std::holds_alternative<LambertShader>(scene.shaders[i])) {
            addTriple(numbers, [=](Scene& s) -> glm::dvec3& { return std::get<LambertShader>(s.shaders[i]).color; });
        } else {
            addTriple(numbers, [=](Scene& s) -> glm::dvec3& { return std::get<ConstantShader>(s.shaders[i]).color; });
        }
    }
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        if (std::holds_alternative<Plane>(scene.nodes[i].geometry)) {
            numbers.push_back({[=](Scene& s) -> double& { return std::get<Plane>(s.nodes[i].geometry).height; }});
        } else {
            addTriple(numbers, [=](Scene& s) -> glm::dvec3& { return std::get<Sphere>(s.nodes[i].geometry).center; });
            numbers.push_back(
                {[=](Scene& s) -> double& { return std::get<Sphere>(s.nodes[i].geometry).radius; }, false});
        }
    }
    return numbers;
}

double roundedTo(double value, int digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*e", digits - 1, value);
    return std::strtod(text, nullptr);
}

// Whether the loader accepts the scene (the shrinker's candidates must be valid scenes).
bool loads(const Scene& scene) {
    try {
        parseScene(sceneToJson(scene), "candidate.json");
        return true;
    } catch (const SceneError&) {
        return false;
    }
}

Scene withoutShader(Scene scene, std::uint32_t index) {
    scene.shaders.erase(scene.shaders.begin() + index);
    scene.shaderNames.erase(scene.shaderNames.begin() + index);
    for (Node& node : scene.nodes) {
        node.shaderIndex -= node.shaderIndex > index ? 1 : 0;
    }
    return scene;
}

bool isUsed(const Scene& scene, std::uint32_t shader) {
    for (const Node& node : scene.nodes) {
        if (node.shaderIndex == shader)
            return true;
    }
    return false;
}

class Shrinker {
public:
    Shrinker(Scene scene, const std::function<bool(const Scene&)>& fails, std::size_t maxTries)
        : best_(std::move(scene)), fails_(fails), triesLeft_(maxTries) {}

    Scene run() {
        for (bool progress = true; progress && triesLeft_ > 0;) {
            const bool dropped = dropParts();
            const bool straightened = straighten();
            const bool rounded = roundNumbers();
            progress = dropped || straightened || rounded;
        }
        return best_;
    }

private:
    // Takes `candidate` if it is valid and still fails.
    bool tryCandidate(const Scene& candidate) {
        if (triesLeft_ == 0 || !loads(candidate))
            return false;
        --triesLeft_;
        if (!fails_(candidate))
            return false;
        best_ = candidate;
        return true;
    }

    template <class Change>
    bool tryChange(Change&& change) {
        Scene candidate = best_;
        change(candidate);
        return tryCandidate(candidate);
    }

    bool dropParts() {
        bool progress = false;
        for (std::size_t i = best_.nodes.size(); i-- > 0;) {
            progress |= tryChange([&](Scene& s) { s.nodes.erase(s.nodes.begin() + std::ptrdiff_t(i)); });
        }
        for (std::size_t i = best_.lights.size(); i-- > 0;) {
            progress |= tryChange([&](Scene& s) { s.lights.erase(s.lights.begin() + std::ptrdiff_t(i)); });
        }
        for (std::uint32_t i = std::uint32_t(best_.shaders.size()); i-- > 0;) {
            if (best_.shaders.size() > 1 && !isUsed(best_, i))
                progress |= tryCandidate(withoutShader(best_, i));
        }
        return progress;
    }

    bool straighten() {
        bool progress = false;
        const CameraSettings straight;
        progress |= best_.camera.aspect && tryChange([](Scene& s) { s.camera.aspect.reset(); });
        progress |= best_.camera.rollDegrees != 0.0 && tryChange([](Scene& s) { s.camera.rollDegrees = 0.0; });
        progress |= best_.camera.yawDegrees != 0.0 && tryChange([](Scene& s) { s.camera.yawDegrees = 0.0; });
        progress |= best_.camera.pitchDegrees != 0.0 && tryChange([](Scene& s) { s.camera.pitchDegrees = 0.0; });
        progress |= best_.camera.fovDegrees != straight.fovDegrees &&
                    tryChange([&](Scene& s) { s.camera.fovDegrees = straight.fovDegrees; });
        progress |= best_.image.sampling != Sampling::Center &&
                    tryChange([](Scene& s) { s.image.sampling = Sampling::Center; });
        progress |=
            best_.image.encoding != Encoding::Srgb && tryChange([](Scene& s) { s.image.encoding = Encoding::Srgb; });
        return progress;
    }

    bool roundNumbers() {
        bool progress = false;
        for (const Number& number : numbersOf(best_)) {
            const double value = number.in(best_);
            std::vector<double> rounder;
            if (number.mayBeZero && value != 0.0)
                rounder.push_back(0.0);
            for (int digits = 1; digits <= 3; ++digits) {
                if (roundedTo(value, digits) != value)
                    rounder.push_back(roundedTo(value, digits));
            }
            for (const double candidate : rounder) {
                if (tryChange([&](Scene& s) { number.in(s) = candidate; })) {
                    progress = true;
                    break;
                }
            }
        }
        return progress;
    }

    Scene best_;
    const std::function<bool(const Scene&)>& fails_;
    std::size_t triesLeft_;
};

}  // namespace

Scene shrinkScene(const Scene& scene, const std::function<bool(const Scene&)>& fails, std::size_t maxTries) {
    return Shrinker(scene, fails, maxTries).run();
}

}  // namespace hexray::test
