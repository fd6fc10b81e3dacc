#pragma once
// libpng's error reporting for snell's PNG reader and writer: libpng calls the error function and expects
// it not to return, so it stores the message and longjmps back to the caller's setjmp(png_jmpbuf(png)).
// Only the PNG writer and readers include this (and so png.h).
#include <png.h>

#include <csetjmp>
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

/// The frame every PNG read shares: creates libpng's read structures on `file`, reads the header and
/// returns `body(png, info)`; a libpng error anywhere (in the header or in `body`) jumps back here and
/// returns `damaged`. `body` must hold only trivially destructible state, since an error leaves its frame
/// by longjmp.
template <class Outcome, class Body>
Outcome read_png_frame(std::FILE* file, PngError& error, Outcome damaged, Body&& body) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, on_png_error, on_png_warning);
  if (!png) return damaged;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    return damaged;
  }
  png_init_io(png, file);
  png_read_info(png, info);
  const Outcome outcome = body(png, info);
  png_destroy_read_struct(&png, &info, nullptr);
  return outcome;
}

}  // namespace snell::io
