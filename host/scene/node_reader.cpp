#include "scene/node_reader.h"

#include <algorithm>
#include <string_view>
#include <utility>

namespace hexray::inline scene {
namespace {

enum class GeometryType { Plane, Sphere };
constexpr std::pair<const char*, GeometryType> kGeometryTypes[] = {{"plane", GeometryType::Plane},
                                                                   {"sphere", GeometryType::Sphere}};

Geometry readGeometry(const JsonReader& geometry) {
    const GeometryType type = geometry.at("type").choice(kGeometryTypes);
    if (type == GeometryType::Plane) {
        geometry.rejectUnknownKeys({"type", "y"});
        return Plane{geometry.at("y").length()};
    }
    geometry.rejectUnknownKeys({"type", "center", "radius"});
    return Sphere{geometry.at("center").position(), geometry.at("radius").length(false)};
}

}  // namespace

// ---------------------------------------------------------------- NodeReader

void NodeReader::read(const Json& element, std::size_t index) {
    if (firstProblem_)
        return;
    try {
        const JsonReader node(element, list_, index);
        node.rejectUnknownKeys({"geometry", "shader"});
        const Geometry geometry = readGeometry(node.at("geometry"));
        add(geometry, node.at("shader").text());
    } catch (const SceneError& problem) {
        firstProblem_ = problem;
    }
}

std::vector<Node> NodeReader::resolve(const std::vector<std::string>& shaderNames) && {
    // By hashing, so that many names against many shaders cost no product of the two.
    std::unordered_map<std::string_view, std::uint32_t> shaderIndexOf;
    for (std::size_t i = 0; i < shaderNames.size(); ++i)
        shaderIndexOf.emplace(shaderNames[i], std::uint32_t(i));
    std::vector<std::uint32_t> shaderIndices;  // for each of names_; shaderNames.size() if unknown
    for (const std::string& name : names_) {
        const auto found = shaderIndexOf.find(name);
        shaderIndices.push_back(found == shaderIndexOf.end() ? std::uint32_t(shaderNames.size()) : found->second);
    }
    std::vector<Node> nodes = std::move(nodes_).take();
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const std::uint32_t nameIndex = nodes[i].shaderIndex;
        nodes[i].shaderIndex = shaderIndices[nameIndex];
        if (nodes[i].shaderIndex == shaderNames.size()) {
            const JsonReader reference(Json(), source_, childPath(elementPath("nodes", i), "shader"));
            reference.fail("unknown shader " + quotedForMessage(names_[nameIndex]) +
                           (shaderNames.empty() ? " (no shaders are defined)"
                                                : " (defined: " + joined(shaderNames) + ")" +
                                                      suggestion(names_[nameIndex], shaderNames)));
        }
    }
    if (firstProblem_)
        throw *firstProblem_;
    return nodes;
}

std::uint32_t NodeReader::nameIndex(const std::string& name) {
    const auto [found, added] = nameIndices_.emplace(name, std::uint32_t(names_.size()));
    if (added)
        names_.push_back(name);
    return found->second;
}

// ---------------------------------------------------------------- UsualNodeShortcut

bool UsualNodeShortcut::string(string_t& value) {
    if (depth_ == 1 && expected_ == Field::Shader) {
        shader_ = value;
    } else if (depth_ == 2 && expected_ == Field::Type) {
        type_ = value;
    } else {
        return false;
    }
    expected_ = Field::None;
    return true;
}

bool UsualNodeShortcut::start_object(std::size_t /*unknown size*/) {
    if (depth_ == 0) {
        *this = UsualNodeShortcut(*nodes_);  // a new element
    } else if (!(depth_ == 1 && expected_ == Field::Geometry)) {
        return false;
    }
    ++depth_;
    expected_ = Field::None;
    return true;
}

bool UsualNodeShortcut::key(string_t& key) {
    if (depth_ == 1) {
        return key == "geometry" ? expect(Field::Geometry) : key == "shader" && expect(Field::Shader);
    }
    if (key == "type")
        return expect(Field::Type);
    if (key == "center")
        return expect(Field::Center);
    if (key == "radius")
        return expect(Field::Radius);
    return key == "y" && expect(Field::Y);
}

bool UsualNodeShortcut::start_array(std::size_t /*unknown size*/) {
    if (depth_ != 2 || expected_ != Field::Center)
        return false;
    depth_ = 3;
    return true;
}

bool UsualNodeShortcut::end_array() {
    if (centerCount_ != 3)
        return false;
    depth_ = 2;
    expected_ = Field::None;
    return true;
}

bool UsualNodeShortcut::end_object() {
    --depth_;
    if (depth_ == 1)
        return readGeometry();
    if (!geometry_ || !seen_[std::size_t(Field::Shader)])
        return false;
    nodes_->add(*geometry_, shader_);
    return true;
}

// A key's value comes next; a key seen before in this element is declined.
bool UsualNodeShortcut::expect(Field field) {
    if (seen_[std::size_t(field)])
        return false;
    seen_[std::size_t(field)] = true;
    expected_ = field;
    return true;
}

bool UsualNodeShortcut::number(double value) {  // as JsonReader::number converts it
    if (depth_ == 3 && centerCount_ < 3) {
        center_[centerCount_++] = value;
        return true;
    }
    if (depth_ != 2 || (expected_ != Field::Radius && expected_ != Field::Y))
        return false;
    (expected_ == Field::Radius ? radius_ : y_) = value;
    expected_ = Field::None;
    return true;
}

// At the end of the geometry object: whether it is a whole sphere or plane, as readGeometry
// would accept it.
bool UsualNodeShortcut::readGeometry() {
    const auto has = [&](Field field) { return seen_[std::size_t(field)]; };
    const bool supportedCenter =
        std::all_of(center_.begin(), center_.end(), [](double c) { return isSupportedLength(c); });
    if (type_ == "sphere" && has(Field::Center) && has(Field::Radius) && !has(Field::Y) &&
        isSupportedLength(radius_, false) && radius_ > 0.0 && supportedCenter) {
        geometry_ = Sphere{{center_[0], center_[1], center_[2]}, radius_};
    } else if (type_ == "plane" && has(Field::Y) && !has(Field::Center) && !has(Field::Radius) &&
               isSupportedLength(y_)) {
        geometry_ = Plane{y_};
    } else {
        return false;
    }
    expected_ = Field::None;
    return true;
}

}  // namespace hexray::scene
