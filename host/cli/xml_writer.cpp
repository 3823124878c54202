#include "cli/xml_writer.h"

#include <new>

#include "util/printable.h"

namespace hexray::cli {
namespace {

const xmlChar* xml(const char* text) {
    return reinterpret_cast<const xmlChar*>(text);
}

}  // namespace

XmlWriter::XmlWriter(Kind kind)
    : buffer_(xmlBufferCreate(), xmlBufferFree), writer_(xmlNewTextWriterMemory(buffer_.get(), 0)), kind_(kind) {
    if (!writer_) {
        throw std::bad_alloc();
    }
    xmlTextWriterSetIndent(writer_, 1);
    if (kind_ == Kind::Xml) {
        xmlTextWriterStartDocument(writer_, nullptr, "UTF-8", nullptr);
    }
}

XmlWriter::~XmlWriter() {
    xmlFreeTextWriter(writer_);
}

void XmlWriter::start(const char* element) {
    xmlTextWriterStartElement(writer_, xml(element));
}

void XmlWriter::end() {
    xmlTextWriterEndElement(writer_);
}

void XmlWriter::fullEnd() {
    xmlTextWriterFullEndElement(writer_);
}

void XmlWriter::attribute(const char* name, const std::string& value) {
    xmlTextWriterWriteAttribute(writer_, xml(name), xml(printable(value).c_str()));
}

void XmlWriter::text(const std::string& value) {
    xmlTextWriterWriteString(writer_, xml(printable(value).c_str()));
}

void XmlWriter::raw(const std::string& value) {
    xmlTextWriterWriteRaw(writer_, xml(value.c_str()));
}

void XmlWriter::element(const char* name, const std::string& value) {
    start(name);
    text(value);
    fullEnd();
}

std::string XmlWriter::finish() {
    xmlTextWriterEndDocument(writer_);
    xmlTextWriterFlush(writer_);
    return {reinterpret_cast<const char*>(xmlBufferContent(buffer_.get())),
            static_cast<std::size_t>(xmlBufferLength(buffer_.get()))};
}

}  // namespace hexray::cli
