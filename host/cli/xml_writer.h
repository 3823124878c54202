#pragma once
// libxml2's text writer into memory, for the XML and HTML hexray writes (--junit, --report): it
// escapes every attribute and text node. Text from outside hexray (scene names, paths, reasons)
// goes through printable() first, so no control character reaches the document.

#include <libxml/xmlwriter.h>

#include <memory>
#include <string>

namespace hexray::cli {

class XmlWriter {
public:
    enum class Kind {
        Xml,   // starts with the XML declaration
        Html,  // no declaration: the caller writes <!DOCTYPE html> with raw()
    };

    explicit XmlWriter(Kind kind = Kind::Xml);
    ~XmlWriter();
    XmlWriter(const XmlWriter&) = delete;
    XmlWriter& operator=(const XmlWriter&) = delete;

    void start(const char* element);
    // Closes the element; an empty one as <name/> (XML, and HTML's void elements such as img).
    void end();
    // Closes the element as </name> even when empty, as HTML needs for all but its void elements.
    void fullEnd();
    void attribute(const char* name, const std::string& value);
    void text(const std::string& value);
    // Written as it is: hexray's own markup, a script or a style sheet.
    void raw(const std::string& value);
    // start(), text() and fullEnd() in one.
    void element(const char* name, const std::string& value);

    // The document, all elements closed.
    std::string finish();

private:
    std::unique_ptr<xmlBuffer, void (*)(xmlBufferPtr)> buffer_;
    xmlTextWriterPtr writer_;
    Kind kind_;
};

}  // namespace hexray::cli
