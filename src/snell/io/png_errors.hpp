#pragma once
// libpng's error reporting for snell's PNG reader and writer: libpng calls the error function and expects
// it not to return, so it stores the message and longjmps back to the caller's setjmp(png_jmpbuf(png)).
// Only png_writer.cpp and png_indices.cpp include this (and so png.h).
#include <png.h>

#include <cstdio>

namespace snell::io {

/// Passed to png_create_*_struct as the error pointer; receives libpng's message.
struct PngError {
  char message[256] = {};
};

inline void on_png_error(png_structp png, png_const_charp message) {
  auto* error = static_cast<PngError*>(png_get_error_ptr(png));
  std::snprintf(error->message, sizeof error->message, "%s", message);
  png_longjmp(png, 1);
}

/// Warnings (e.g. about ancillary chunks) do not stop a read or write.
inline void on_png_warning(png_structp, png_const_charp) {}

}  // namespace snell::io
