#pragma once
// A scene file's "nodes", read one element at a time as the parser completes each (see
// parseSceneJson), so that a million nodes never exist as one document.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "scene/json_reader.h"
#include "scene/scene.h"
#include "scene/scene_json_parser.h"
#include "util/chunked_list.h"

namespace hexray::inline scene {

// The nodes, which may come before the shaders they name: a node keeps its shader as an index
// into the names seen so far until the scene's shaders are known. Reading stops at the first
// bad node, and its problem is raised only by resolve(), which the scene reader calls where it
// reaches the nodes, so problems are reported in the same order as if the document were read
// whole.
class NodeReader {
public:
    explicit NodeReader(const std::string& source) : source_(source), list_(noElements_, source, "nodes") {}
    NodeReader(const NodeReader&) = delete;
    NodeReader& operator=(const NodeReader&) = delete;

    // Element `index` of "nodes", checked as the format requires.
    void read(const Json& element, std::size_t index);

    // A node read by other means, which must have checked it as read() does.
    void add(const Geometry& geometry, const std::string& shaderName) {
        nodes_.push_back(Node{geometry, nameIndex(shaderName)});
    }

    // The nodes, with their shader indices into `shaderNames`.
    std::vector<Node> resolve(const std::vector<std::string>& shaderNames) &&;

private:
    std::uint32_t nameIndex(const std::string& name);

    const std::string& source_;
    const Json noElements_ = Json::array();  // the parser keeps no elements of "nodes":
    const JsonReader list_;                  // this reader is only their parent, for their paths
    ChunkedList<Node> nodes_;                // shaderIndex: into names_ until resolved
    std::vector<std::string> names_;
    std::unordered_map<std::string, std::uint32_t> nameIndices_;
    std::optional<SceneError> firstProblem_;
};

// Reads a "nodes" element of the usual shape straight from the parser's events, without the
// document NodeReader::read needs (which costs more than parsing the text): {"geometry":
// {"type": "sphere", "center": [x, y, z], "radius": r > 0} or {"type": "plane", "y": h},
// "shader": name}, keys in any order. It only recognises valid nodes; anything else, a repeated
// key included, it declines, and the file is read the general way, which names the problem.
class UsualNodeShortcut final : public NodeShortcut {
public:
    explicit UsualNodeShortcut(NodeReader& nodes) : nodes_(&nodes) {}

    bool null() override { return false; }
    bool boolean(bool /*value*/) override { return false; }
    bool number_integer(number_integer_t value) override { return number(double(value)); }
    bool number_unsigned(number_unsigned_t value) override { return number(double(value)); }
    bool number_float(number_float_t value, const string_t& /*literal*/) override { return number(value); }
    bool string(string_t& value) override;
    bool binary(binary_t& /*value*/) override { return false; }
    bool start_object(std::size_t /*unknown size*/) override;
    bool key(string_t& key) override;
    bool end_object() override;
    bool start_array(std::size_t /*unknown size*/) override;
    bool end_array() override;
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

private:
    enum class Field { None, Geometry, Shader, Type, Center, Radius, Y, Count };

    bool expect(Field field);
    bool number(double value);
    bool readGeometry();

    NodeReader* nodes_;
    // What the parser has reported of the element so far.
    int depth_ = 0;                 // 0: between elements, 1: in the node, 2: in its geometry, 3: in the centre
    Field expected_ = Field::None;  // the field whose value comes next
    std::array<bool, std::size_t(Field::Count)> seen_{};
    std::string shader_;
    std::string type_;
    std::array<double, 3> center_{};
    int centerCount_ = 0;
    double radius_ = 0.0;
    double y_ = 0.0;
    std::optional<Geometry> geometry_;
};

}  // namespace hexray::scene
