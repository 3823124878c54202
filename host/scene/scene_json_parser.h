#pragma once
// The JSON layer of scene files: text to a document, rejecting what only the parser sees (a
// syntax error at its line:column; a duplicate key, nesting deeper than 64 levels or a number
// too large for a double at its JSON path) with a SceneError. Comments (// to the end of the
// line, /* ... */) are read as whitespace, and a UTF-8 byte order mark is skipped. Time and
// memory are linear in the text.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene_loader.h"

namespace hexray::inline scene {

// Receives each element of one of the root object's arrays read an element at a time ("nodes"
// and "lights"), with its index, as soon as the parser has read it whole. The element is not kept:
// in the document, that array is empty, so a scene of a million nodes or lights never exists as
// one document (some 700 bytes an element).
using ElementSink = std::function<void(const nlohmann::json& element, std::size_t index)>;

nlohmann::json parseSceneJson(const std::string& text, const std::string& sourceName, const ElementSink& takeNode,
                              const ElementSink& takeLight, const ParseProgress& progress = {});

// Reads the events of each element of the root's "nodes" in place of a document: it takes an
// element by returning true to each of its events, or declines it by returning false. (No
// parse_error reaches it.) A shortcut for elements of a shape known in advance.
using NodeShortcut = nlohmann::json_sax<nlohmann::json>;

// As above, with every element of the root's "nodes" read by `shortcut`; nullopt once it
// declines one, and the text must then be parsed the general way.
std::optional<nlohmann::json> parseSceneJson(const std::string& text, const std::string& sourceName,
                                             NodeShortcut& shortcut, const ElementSink& takeLight,
                                             const ParseProgress& progress = {});

}  // namespace hexray::scene
