#pragma once
// Machine-readable results (`--json FILE|-`; docs/json-output.md and its schema,
// docs/schemas/hexray-results.schema.json). Every command's document starts with the same fields,
// so that a CI script reads any of them the same way; JSON has no infinity or NaN, so a value that
// does not apply, or is not finite, is null.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "vulkan/vulkan_context.h"

namespace hexray::cli {

// Bumped when a field changes meaning or goes away; new fields keep the number.
inline constexpr int kJsonSchemaVersion = 1;

// {"schema": "hexray-<command>/<version>", "command", "hexray": {"version", "git"}}.
nlohmann::json jsonDocument(const std::string& command);

// {"name", "driver", "type", "api"}: the Vulkan device a command used.
nlohmann::json jsonDevice(const DeviceInfo& device);

// A finite number as itself, anything else (or none) as null.
nlohmann::json jsonNumber(double value);
nlohmann::json jsonNumber(const std::optional<double>& value);

// The exit code, its name (exitCodeName) and the error messages printed so far (printError):
// "exit": {"code", "name", "messages"}. Also "timings_ms.wall", from the process's start.
void recordExit(nlohmann::json& document, int code);

// "success", "tolerance_exceeded", "bad_input", … (cli/commands.h's ExitCode).
const char* exitCodeName(int code);

// Milliseconds since this process started (since its static initialisation, close enough).
double processMilliseconds();

// Writes `document` to `path` ("-" or a path to standard output: the data's descriptor) whole or
// not at all (io/output_file.h).
void writeJson(const std::string& path, const nlohmann::json& document);

// The end of a command run with `--json PATH` (nothing when PATH is empty): records `code` and
// writes the document. Returns `code`, or the failure's exit code (kOutputFailed) when the
// document cannot be written.
int finishJson(const std::string& path, nlohmann::json& document, int code);

}  // namespace hexray::cli
