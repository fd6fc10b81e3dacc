#include "cli/preview/sdl_library.hpp"

#include <dlfcn.h>

#include <mutex>

namespace snell::cli {

namespace {

template <class F>
bool resolve(void* handle, const char* name, F& out, std::string& why) {
  out = reinterpret_cast<F>(dlsym(handle, name));
  if (!out) why = std::string("libSDL2 has no ") + name;
  return out != nullptr;
}

}  // namespace

const SdlLibrary* load_sdl_library(std::string& why) {
  static SdlLibrary library{};
  static std::string error;
  static std::once_flag once;
  std::call_once(once, [] {
    // Never closed: SDL's threads and atexit handlers may outlive any scope here.
    void* h = dlopen("libSDL2-2.0.so.0", RTLD_NOW | RTLD_LOCAL);
    if (!h) {
      const char* message = dlerror();
      error = std::string("cannot load SDL2: ") + (message ? message : "unknown error");
      return;
    }
    SdlLibrary& l = library;
    const bool ok = resolve(h, "SDL_SetHint", l.SetHint, error) && resolve(h, "SDL_Init", l.Init, error) &&
                    resolve(h, "SDL_Quit", l.Quit, error) && resolve(h, "SDL_GetError", l.GetError, error) &&
                    resolve(h, "SDL_CreateWindow", l.CreateWindow, error) &&
                    resolve(h, "SDL_DestroyWindow", l.DestroyWindow, error) &&
                    resolve(h, "SDL_HideWindow", l.HideWindow, error) &&
                    resolve(h, "SDL_SetWindowTitle", l.SetWindowTitle, error) &&
                    resolve(h, "SDL_CreateRenderer", l.CreateRenderer, error) &&
                    resolve(h, "SDL_DestroyRenderer", l.DestroyRenderer, error) &&
                    resolve(h, "SDL_GetRendererOutputSize", l.GetRendererOutputSize, error) &&
                    resolve(h, "SDL_RenderClear", l.RenderClear, error) &&
                    resolve(h, "SDL_RenderCopy", l.RenderCopy, error) &&
                    resolve(h, "SDL_RenderPresent", l.RenderPresent, error) &&
                    resolve(h, "SDL_RenderReadPixels", l.RenderReadPixels, error) &&
                    resolve(h, "SDL_CreateTexture", l.CreateTexture, error) &&
                    resolve(h, "SDL_DestroyTexture", l.DestroyTexture, error) &&
                    resolve(h, "SDL_UpdateTexture", l.UpdateTexture, error) &&
                    resolve(h, "SDL_PollEvent", l.PollEvent, error);
    if (!ok) library = {};
  });
  if (!library.Init) {
    why = error;
    return nullptr;
  }
  return &library;
}

}  // namespace snell::cli
