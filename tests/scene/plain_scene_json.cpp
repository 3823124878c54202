// Prints a scene file as plain JSON, its comments dropped as the loader drops them (nlohmann's
// parser with ignore_comments, scene/scene_json_parser.cpp), for tools that read only plain JSON:
// tests/scene/validate_scenes.py checks scene files against docs/schemas/hexray-scene.schema.json.
// usage: plain_scene_json FILE; exit 1 with the parser's message on standard error when it is not JSON.

#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: plain_scene_json FILE\n";
        return 2;
    }
    std::ifstream in(argv[1], std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in.good() && !in.eof()) {
        std::cerr << argv[1] << ": cannot read\n";
        return 1;
    }
    constexpr bool kIgnoreComments = true;
    const nlohmann::json document = nlohmann::json::parse(text, nullptr, false, kIgnoreComments);
    if (document.is_discarded()) {
        std::cerr << argv[1] << ": not JSON\n";
        return 1;
    }
    // Keys are kept as nlohmann sorts them; a schema does not care about the order.
    std::cout << document.dump() << '\n';
    return 0;
}
