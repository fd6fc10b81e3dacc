#pragma once
// The interface between snell and its Assimp plugin (src/plugins/assimp_plugin.cpp). Why a plugin: Debian's
// Assimp and the libraries it pulls in (draco, minizip, zlib, brotli) took about a third of snell's start-up
// (dynamic relocation and page faults, measured with perf on an empty scene), paid by every render, while
// only scenes with `mesh { "file" }` need them. Plugin and program are built together by one compiler, so
// the C++ result type may cross; exceptions may not, hence the status code.
#include <cstddef>

#include "snell/io/mesh_import.hpp"

extern "C" {

/// Reads the model file `path` with Assimp into `out`. Returns 0 on success; otherwise writes the reason
/// into `error` (NUL-terminated, at most `error_size` bytes).
using SnellAssimpImport = int (*)(const char* path, snell::io::ImportedMesh* out, char* error,
                                  size_t error_size);
}
