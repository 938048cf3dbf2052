// Transfer functions as JSON files, read strictly and written atomically.
#pragma once

#include <string>

#include "core/transfer_function.h"

namespace ewa {

// Format: {"opacity": [[v, a], ...], "color": [[v, r, g, b], ...], "opacity_unit_distance": d}.
// Parses the JSON text of a transfer function. "opacity" is required; "color" (default: none,
// which draws white) and "opacity_unit_distance" (default 1) are optional; "name" and
// "description" strings are allowed and ignored; any other key is an error (catches typos).
// Points are sorted by value, then validated. Throws std::runtime_error with one line
// "<nameForErrors>: <problem>".
TransferFunction parseTransferFunctionJson(const std::string& text,
                                           const std::string& nameForErrors);

// Reads and parses `path`. Throws std::runtime_error("<path>: <problem>").
TransferFunction loadTransferFunction(const std::string& path);

// The JSON text saveTransferFunction writes: one point per line, numbers that read back exactly.
std::string transferFunctionToJson(const TransferFunction& tf);

// Sorts a copy of `tf`, validates it, writes it to a temporary file beside `path` and renames it
// into place, so a crash never leaves half a file. Throws std::runtime_error("<path>: <problem>").
void saveTransferFunction(const std::string& path, const TransferFunction& tf);

// "dir/name.tf.json" beside "dir/name.ext": a transfer function kept with its volume; for
// channel C > 0 of a multi-channel file "dir/name.cC.tf.json" (stains differ in range).
std::string sidecarTransferFunctionPath(const std::string& volumePath, int channel = 0);

}  // namespace ewa
