// The preview window of a build without SDL2 (cmake found no libsdl2-dev): +D renders on without one.
#include "cli/preview/preview_window.hpp"

namespace snell::cli {

std::unique_ptr<PreviewWindow> open_preview_window(int, int, const std::string&, const io::Encoding&,
                                                   std::string& why) {
  why = "this snell was built without SDL2 (install libsdl2-dev and rebuild)";
  return nullptr;
}

}  // namespace snell::cli
