#pragma once
// A scene file's "lights", read one element at a time as the parser completes each (see
// parseSceneJson), so that a file of millions of lights never exists as one document.

#include <optional>
#include <string>
#include <vector>

#include "scene/json_reader.h"
#include "scene/scene.h"
#include "util/chunked_list.h"

namespace hexray::inline scene {

// Reading stops at the first bad light, and its problem is raised only by take(), which the scene
// reader calls where it reaches the lights, so problems are reported in the same order as if the
// document were read whole.
class LightReader {
public:
    explicit LightReader(const std::string& source) : list_(noElements_, source, "lights") {}
    LightReader(const LightReader&) = delete;
    LightReader& operator=(const LightReader&) = delete;

    // Element `index` of "lights", checked as the format requires.
    void read(const Json& element, std::size_t index);

    // The lights, in a vector of just their number.
    std::vector<PointLight> take() &&;

private:
    const Json noElements_ = Json::array();  // the parser keeps no elements of "lights":
    const JsonReader list_;                  // this reader is only their parent, for their paths
    ChunkedList<PointLight> lights_;
    std::optional<SceneError> firstProblem_;
};

// One light, checked as the format requires.
PointLight readLight(const JsonReader& light);

}  // namespace hexray::scene
