#include "scene/scene_json_parser.h"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

#include "scene/json_path.h"
#include "scene/scene_loader.h"
#include "util/printable.h"

namespace hexray::inline scene {
namespace {

using Json = nlohmann::json;

// Scene files nest 5 levels deep; anything far deeper is not a scene.
constexpr std::size_t kMaxNesting = 64;

// nlohmann reports the byte offset (1-based) of the last character it read; people want
// line:column. Columns count characters (UTF-8 code points), not bytes.
std::string lineAndColumn(const std::string& text, std::size_t byte) {
    const std::size_t offset = std::min(byte == 0 ? 0 : byte - 1, text.size());
    std::size_t line = 1;
    std::size_t column = 1;
    const std::size_t start = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;  // a BOM takes no column
    for (std::size_t i = std::min(start, offset); i < offset; ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++line;
            column = 1;
        } else if ((c & 0xC0) != 0x80) {  // not a UTF-8 continuation byte
            ++column;
        }
    }
    return std::to_string(line) + ":" + std::to_string(column);
}

// "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ..." -> "syntax error ...".
std::string parseErrorDetail(const std::string& what) {
    const std::size_t errorAt = what.find("parse error");
    if (errorAt == std::string::npos)
        return what;
    const std::size_t colon = what.find(": ", errorAt);
    std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
    // nlohmann quotes the whole token it stopped in ("last read: '...'"), which may be a huge string.
    const std::string kLastRead = "last read: '";
    const std::size_t tokenStart = detail.find(kLastRead);
    if (tokenStart == std::string::npos)
        return detail;
    const std::size_t first = tokenStart + kLastRead.size();
    const std::size_t expected = detail.rfind("'; expected");
    const std::size_t last = expected != std::string::npos && expected >= first ? expected : detail.rfind('\'');
    if (last == std::string::npos || last < first || last - first <= kMaxShown)
        return detail;
    std::size_t cut = first + kMaxShown;
    while (cut > first && (static_cast<unsigned char>(detail[cut]) & 0xC0) == 0x80)
        --cut;  // whole UTF-8 characters
    return detail.substr(0, cut) + "..." + detail.substr(last);
}

// "[json.exception.out_of_range.406] number overflow parsing '1e999'" -> "1e999".
std::string overflowingLiteral(const std::string& what) {
    const std::size_t open = what.find('\'');
    const std::size_t close = what.rfind('\'');
    if (open == std::string::npos || close <= open)
        return "a number too large for a double";
    return what.substr(open + 1, close - open - 1);
}

// Builds the document from nlohmann's SAX events, checking as it goes. (nlohmann's own parser
// with a callback could check too, but it scans the whole enclosing container at the end of
// every object: quadratic in a long "nodes" array.) Paths are built only for a message:
// storing one per level would make deep nesting cost quadratic time and memory.
class DocumentBuilder {
public:
    // Elements of the root's "nodes" go to `takeNode` as documents, or, with a `shortcut`, to it
    // as events; those of its "lights" to `takeLight` as documents.
    DocumentBuilder(const std::string& text, const std::string& source, const ElementSink* takeNode,
                    NodeShortcut* shortcut, const ElementSink& takeLight)
        : text_(text), source_(source), takeNode_(takeNode), shortcut_(shortcut), takeLight_(takeLight) {}

    Json takeDocument() { return std::move(root_); }

    // ---- nlohmann's SAX interface. A problem throws SceneError; false means the shortcut
    // declined an element, which ends the parse.
    bool null() {
        return addValue([] { return Json(nullptr); }, [](NodeShortcut& shortcut) { return shortcut.null(); });
    }
    bool boolean(bool value) {
        return addValue([&] { return Json(value); }, [&](NodeShortcut& shortcut) { return shortcut.boolean(value); });
    }
    bool number_integer(Json::number_integer_t value) {
        return addValue([&] { return Json(value); },
                        [&](NodeShortcut& shortcut) { return shortcut.number_integer(value); });
    }
    bool number_unsigned(Json::number_unsigned_t value) {
        return addValue([&] { return Json(value); },
                        [&](NodeShortcut& shortcut) { return shortcut.number_unsigned(value); });
    }
    bool number_float(Json::number_float_t value, const Json::string_t& literal) {
        return addValue([&] { return Json(value); },
                        [&](NodeShortcut& shortcut) { return shortcut.number_float(value, literal); });
    }
    bool string(Json::string_t& value) {
        return addValue([&] { return Json(value); }, [&](NodeShortcut& shortcut) { return shortcut.string(value); });
    }
    bool binary(Json::binary_t& value) {  // never from JSON text
        return addValue([&] { return Json::binary(value); },
                        [&](NodeShortcut& shortcut) { return shortcut.binary(value); });
    }
    bool start_object(std::size_t size) {
        return open(
            false, [] { return Json::object(); }, [&](NodeShortcut& shortcut) { return shortcut.start_object(size); });
    }
    bool start_array(std::size_t size) {
        return open(
            true, [] { return Json::array(); }, [&](NodeShortcut& shortcut) { return shortcut.start_array(size); });
    }
    bool end_object() {
        return close([](NodeShortcut& shortcut) { return shortcut.end_object(); });
    }
    bool end_array() {
        return close([](NodeShortcut& shortcut) { return shortcut.end_array(); });
    }

    bool key(Json::string_t& key) {
        Frame& object = frames_.back();
        object.currentKey = key;
        if (shortcutTakes(3)) {
            return shortcut_->key(key);  // which declines a repeated key
        }
        const auto [slot, added] = object.container->get_ref<Json::object_t&>().try_emplace(key);
        // A document keeps one value per key; the earlier one would silently vanish.
        if (!added)
            throw SceneError(source_ + ": " + pendingPath() + ": duplicate key");
        object.slot = &slot->second;
        return true;
    }

    // nlohmann passes its exception here instead of throwing it: a parse_error, or out_of_range
    // for a literal like 1e999, before that reaches the document.
    bool parse_error(std::size_t /*position*/, const std::string& /*last token*/, const Json::exception& error) {
        if (const auto* syntax = dynamic_cast<const Json::parse_error*>(&error)) {
            throw SceneError(source_ + ":" + lineAndColumn(text_, syntax->byte) +
                             ": JSON syntax error: " + printable(parseErrorDetail(error.what())));
        }
        throw SceneError(source_ + ": " + displayPath(pendingPath()) + ": must be a finite number (got " +
                         overflowingLiteral(error.what()) + ")");
    }

private:
    // The root object's arrays whose elements are handed over one by one.
    enum class Streamed { No, Nodes, Lights };

    struct Frame {
        Json* container = nullptr;  // null inside an element the shortcut reads
        bool isArray = false;
        Streamed streamed = Streamed::No;
        std::size_t nextIndex = 0;  // arrays: index of the next element
        std::string currentKey;     // objects: key of the value being read
        Json* slot = nullptr;       // objects: where that value goes
    };

    // Where the value the parser is reading now (and has not yet reported) belongs.
    std::string pendingPath() const {
        std::string path;
        for (std::size_t i = 0; i < frames_.size(); ++i) {
            const Frame& frame = frames_[i];
            // An array's index has already moved past the elements its open children are in.
            const bool pending = i + 1 == frames_.size();
            path = frame.isArray ? elementPath(path, frame.nextIndex - (pending ? 0 : 1))
                                 : childPath(path, frame.currentKey);
        }
        return path;
    }

    // Whether the shortcut reads what the parser reports now: true inside an element of the
    // root's "nodes", which begins at depth 2 (an element's value or its start) and has keys,
    // ends and values at depth 3 and beyond.
    bool shortcutTakes(std::size_t depth) const {
        return shortcut_ && frames_.size() >= depth && frames_[1].streamed == Streamed::Nodes;
    }

    // The pending value has begun: an array's next one gets the next index.
    void startValue() {
        if (!frames_.empty() && frames_.back().isArray)
            ++frames_.back().nextIndex;
    }

    // Puts a value where the innermost open container expects its next one.
    Json* place(Json&& value) {
        startValue();
        if (frames_.empty()) {
            root_ = std::move(value);
            return &root_;
        }
        Frame& parent = frames_.back();
        if (parent.isArray) {
            parent.container->push_back(std::move(value));
            return &parent.container->back();
        }
        *parent.slot = std::move(value);
        return parent.slot;
    }

    template <class MakeValue, class Forward>
    bool addValue(const MakeValue& makeValue, const Forward& forward) {
        if (shortcutTakes(2)) {
            startValue();
            return forward(*shortcut_);
        }
        place(makeValue());
        handOverCompleteElement();
        return true;
    }

    template <class MakeContainer, class Forward>
    bool open(bool isArray, const MakeContainer& makeContainer, const Forward& forward) {
        if (frames_.size() >= kMaxNesting) {
            throw SceneError(source_ + ": " + displayPath(pendingPath()) + ": nested deeper than " +
                             std::to_string(kMaxNesting) + " levels");
        }
        if (shortcutTakes(2)) {
            startValue();
            frames_.push_back(Frame{nullptr, isArray, Streamed::No, 0, {}, nullptr});
            return forward(*shortcut_);
        }
        const bool rootArray = isArray && frames_.size() == 1 && !frames_[0].isArray;
        const Streamed streamed = !rootArray                          ? Streamed::No
                                  : frames_[0].currentKey == "nodes"  ? Streamed::Nodes
                                  : frames_[0].currentKey == "lights" ? Streamed::Lights
                                                                      : Streamed::No;
        Json* placed = place(makeContainer());
        frames_.push_back(Frame{placed, isArray, streamed, 0, {}, nullptr});
        return true;
    }

    template <class Forward>
    bool close(const Forward& forward) {
        const bool forwarding = shortcutTakes(3);
        frames_.pop_back();
        if (forwarding) {
            return forward(*shortcut_);
        }
        handOverCompleteElement();
        return true;
    }

    // Called when a value is complete: if it is an element of the root's "nodes" or "lights", its
    // sink takes it and the document drops it.
    void handOverCompleteElement() {
        if (frames_.size() != 2 || frames_[1].streamed == Streamed::No)
            return;
        Json& elements = *frames_[1].container;
        const ElementSink& take = frames_[1].streamed == Streamed::Nodes ? *takeNode_ : takeLight_;
        take(elements.back(), frames_[1].nextIndex - 1);
        elements.get_ref<Json::array_t&>().pop_back();
    }

    const std::string& text_;
    const std::string& source_;
    const ElementSink* takeNode_;
    NodeShortcut* shortcut_;
    const ElementSink& takeLight_;
    Json root_;
    std::vector<Frame> frames_;
};

// The text as nlohmann's parser reads it, a character at a time, telling `progress` every
// kProgressStep bytes how far it has got: one comparison a character, as the parser's own.
class ProgressIterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    static constexpr std::size_t kProgressStep = std::size_t{1} << 20;

    ProgressIterator(const std::string& text, std::size_t offset, const ParseProgress* progress)
        : at_(text.data() + offset), begin_(text.data()), size_(text.size()), progress_(progress) {
        setNextReport();
    }

    reference operator*() const { return *at_; }
    ProgressIterator& operator++() {
        if (++at_ == nextReport_) {
            (*progress_)(std::size_t(at_ - begin_), size_);
            setNextReport();
        }
        return *this;
    }
    ProgressIterator operator++(int) {
        ProgressIterator before = *this;
        ++*this;
        return before;
    }
    bool operator==(const ProgressIterator& other) const { return at_ == other.at_; }

private:
    void setNextReport() {
        const std::size_t offset = std::size_t(at_ - begin_);
        nextReport_ = *progress_ && size_ - offset > kProgressStep ? at_ + kProgressStep : nullptr;
    }

    const char* at_;
    const char* begin_;
    std::size_t size_;
    const ParseProgress* progress_;
    const char* nextReport_ = nullptr;
};

// nlohmann's SAX parse of `text`, reporting progress if asked.
bool saxParse(const std::string& text, DocumentBuilder& builder, const ParseProgress& progress) {
    // Comments (// and /* */) are read as whitespace: people annotate their scenes.
    constexpr bool kStrict = true;
    constexpr bool kIgnoreComments = true;
    if (!progress)
        return Json::sax_parse(text, &builder, Json::input_format_t::json, kStrict, kIgnoreComments);
    return Json::sax_parse(ProgressIterator(text, 0, &progress), ProgressIterator(text, text.size(), &progress),
                           &builder, Json::input_format_t::json, kStrict, kIgnoreComments);
}

}  // namespace

Json parseSceneJson(const std::string& text, const std::string& sourceName, const ElementSink& takeNode,
                    const ElementSink& takeLight, const ParseProgress& progress) {
    DocumentBuilder builder(text, sourceName, &takeNode, nullptr, takeLight);
    saxParse(text, builder, progress);
    return builder.takeDocument();
}

std::optional<Json> parseSceneJson(const std::string& text, const std::string& sourceName, NodeShortcut& shortcut,
                                   const ElementSink& takeLight, const ParseProgress& progress) {
    DocumentBuilder builder(text, sourceName, nullptr, &shortcut, takeLight);
    if (!saxParse(text, builder, progress))
        return std::nullopt;
    return builder.takeDocument();
}

}  // namespace hexray::scene
