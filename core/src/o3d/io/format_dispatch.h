// SPDX-License-Identifier: MIT
#pragma once
/// @file format_dispatch.h
/// @brief Choosing a file format from an explicit name or, for "" / "auto", from the path's extension:
/// shared by the point-cloud, mesh and image readers so that they accept and report formats alike.
#include <cstddef>
#include <string>
#include <string_view>

#include "o3d/utility/error.h"

namespace o3d::io::detail {

template <typename Format>
struct FormatName {
    const char* name;  ///< lower case, as accepted in `format` and as an extension
    Format format;
};

inline std::string lowercase(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return out;
}

/// @brief The extension of the last path component without its dot ("" when it has none).
inline std::string extension_of(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
    return has_ext ? path.substr(dot + 1) : std::string();
}

/// @brief `format` by name (case-insensitive), or by the extension of `*path` when `format` is "" or
/// "auto". Unknown names are Unsupported; "auto" without a path (in-memory data) is InvalidArgument.
/// `kind` names the data in messages ("point-cloud", "triangle-mesh", "image").
template <typename Format, size_t N>
Format resolve_format(const FormatName<Format> (&table)[N], const char* kind, const std::string& format,
                      const std::string* path) {
    std::string known;
    for (const auto& entry : table) known += (known.empty() ? "" : ", ") + std::string(entry.name);
    const auto lookup = [&](const std::string& name, Format& out) {
        const std::string n = lowercase(name);
        for (const auto& entry : table)
            if (n == entry.name) {
                out = entry.format;
                return true;
            }
        return false;
    };
    Format f{};
    if (!format.empty() && lowercase(format) != "auto") {
        if (!lookup(format, f))
            throw Unsupported("unknown " + std::string(kind) + " format '" + format + "' (known: " + known + ")");
        return f;
    }
    if (!path) throw InvalidArgument("a format is required for in-memory data (known: " + known + ")");
    const std::string ext = extension_of(*path);
    if (!lookup(ext, f))
        throw Unsupported("cannot tell the " + std::string(kind) + " format of '" + *path + "' from its extension" +
                          (ext.empty() ? std::string(" (it has none)") : " '." + ext + "'") + " (known: " + known +
                          ")");
    return f;
}

}  // namespace o3d::io::detail
