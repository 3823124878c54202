#pragma once
// Options whose values are names: one table per enum is the only list of its names, read by the
// help text, the check and the conversion alike.

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "gpu/render_plan.h"
#include "precision/precision.h"
#include "util/closest_name.h"

namespace hexray::cli {

template <class Enum>
using NameTable = std::vector<std::pair<std::string, Enum>>;

inline const NameTable<Backend> kBackendNames{{"auto", Backend::Auto}, {"gpu", Backend::Gpu}, {"cpu", Backend::Cpu}};
inline const NameTable<PixelBackend> kPixelBackendNames{
    {"both", PixelBackend::Both}, {"gpu", PixelBackend::Gpu}, {"cpu", PixelBackend::Cpu}};
inline const NameTable<WatchKernel> kWatchKernelNames{{"tiered", WatchKernel::Tiered},
                                                      {"buffered", WatchKernel::Buffered},
                                                      {"specialised", WatchKernel::Specialised},
                                                      {"data-driven", WatchKernel::DataDriven}};
inline const NameTable<Culling> kCullingNames{{"auto", Culling::Auto}, {"on", Culling::On}, {"off", Culling::Off}};

// The precisions, in the order the help lists them (their names are precision.h's).
inline NameTable<Precision> precisionNames() {
    NameTable<Precision> names;
    for (const Precision precision :
         {Precision::Auto, Precision::F32, Precision::F64, Precision::F32Naive, Precision::F32Certified}) {
        names.emplace_back(std::string(precisionName(precision)), precision);
    }
    return names;
}

// The name `value` has in `names` (as the command line spells it, for --json).
template <class Enum>
std::string nameOf(const NameTable<Enum>& names, Enum value) {
    for (const auto& [name, named] : names) {
        if (named == value) {
            return name;
        }
    }
    return "";
}

// An option `flags` setting `value` by one of `names`; anything else is refused naming them all.
template <class Enum>
CLI::Option* addNamedOption(CLI::App& command, const std::string& flags, Enum& value, const NameTable<Enum>& names,
                            const std::string& help) {
    std::string list;
    std::string current;
    for (const auto& [name, named] : names) {
        list += (list.empty() ? "" : ",") + name;
        current = named == value ? name : current;
    }
    list = "{" + list + "}";
    // The name becomes the enum's number, which CLI11 then converts; a number typed in is refused.
    CLI::Validator byName(
        [names, list](std::string& input) -> std::string {
            for (const auto& [name, named] : names) {
                if (name == input) {
                    input = std::to_string(static_cast<int>(named));
                    return {};
                }
            }
            std::vector<std::string> known;
            for (const auto& entry : names) {
                known.push_back(entry.first);
            }
            const std::optional<std::string> near = closestName(input, known);  // "2" is no misspelt "on"
            return input + " not in " + list + (near ? "; did you mean " + *near + "?" : "");
        },
        list);
    return command.add_option(flags, value, help)->transform(byName)->type_name("")->default_str(current);
}

}  // namespace hexray::cli
