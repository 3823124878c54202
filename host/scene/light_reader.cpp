#include "scene/light_reader.h"

#include <utility>

namespace hexray::inline scene {

PointLight readLight(const JsonReader& light) {
    light.rejectUnknownKeys({"position", "color", "intensity"});
    PointLight result;
    result.position = light.at("position").position();
    result.color = light.colourOr("color", result.color);
    result.intensity = light.at("intensity").intensity();
    return result;
}

void LightReader::read(const Json& element, std::size_t index) {
    if (firstProblem_)
        return;
    try {
        lights_.push_back(readLight(JsonReader(element, list_, index)));
    } catch (const SceneError& problem) {
        firstProblem_ = problem;
    }
}

std::vector<PointLight> LightReader::take() && {
    if (firstProblem_)
        throw *firstProblem_;
    return std::move(lights_).take();
}

}  // namespace hexray::scene
