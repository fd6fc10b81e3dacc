#pragma once
// Fuzz targets for the files a scene or a resumed render makes snell read (issue 12): the PNG readers
// (libpng palette indices for height fields, OpenImageIO for image maps), the other image formats through
// the OpenImageIO plugin, resume files, df3 density files and model files for `mesh { "file" }`. Shared by
// the libFuzzer programs (SNELL_FUZZ=ON) and the replay test in tests/fuzz, which runs them from an ordinary
// build.
//
// Each function writes the bytes to a private temporary file (the readers take paths, as the parser and
// the CLI call them) and reads it back. It returns true when the file was accepted and false when the
// reader refused it with its documented error; any other outcome (a crash, a sanitizer report, another
// exception) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

namespace snell::fuzz {

/// A palette PNG's indices (height_field) and then its colours (image_map).
bool read_png_bytes(const uint8_t* data, size_t size);

/// The first byte picks the format (the plugin chooses its reader by extension); the rest is the file.
bool read_image_bytes(const uint8_t* data, size_t size);
/// The extensions read_image_bytes chooses from, in the order of its first byte (modulo their count).
extern const char* const kImageFuzzExtensions[];
extern const size_t kImageFuzzExtensionCount;

/// A resume file checked against the fingerprint and image size it names itself (bytes 12..27), so that
/// the reader gets past those checks; sizes over 1024 are replaced by 64.
bool read_resume_bytes(const uint8_t* data, size_t size);

/// A df3 density file (texture/density_file.hpp) read, then sampled by the density_file pattern at a few
/// points with and without interpolation; every value must lie in [0, 1].
bool read_df3_bytes(const uint8_t* data, size_t size);

/// A model file through io::import_mesh (Assimp, and snell's own binary PLY reader): the first byte picks
/// the extension, the rest is the file. An accepted mesh must have finite vertices and indices in range.
bool read_mesh_bytes(const uint8_t* data, size_t size);
/// The extensions read_mesh_bytes chooses from, in the order of its first byte (modulo their count).
extern const char* const kMeshFuzzExtensions[];
extern const size_t kMeshFuzzExtensionCount;

/// A file in this process's private temporary folder holding `size` bytes, named with `extension`.
std::string write_fuzz_file(const uint8_t* data, size_t size, const std::string& extension);

}  // namespace snell::fuzz
