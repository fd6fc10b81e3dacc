#pragma once
// SDL2, loaded with dlopen when a render window is first opened. Why not link it: libSDL2 pulls in about
// forty shared libraries (PulseAudio, ALSA, X11, Wayland, audio codecs) that the dynamic loader would map
// and relocate at every start of snell, while only `+D` uses them; a short render pays that on every run.
#include <SDL.h>

#include <string>

namespace snell::cli {

/// The SDL functions the render window calls, resolved from the loaded library.
struct SdlLibrary {
  decltype(&SDL_SetHint) SetHint;
  decltype(&SDL_Init) Init;
  decltype(&SDL_Quit) Quit;
  decltype(&SDL_GetError) GetError;
  decltype(&SDL_CreateWindow) CreateWindow;
  decltype(&SDL_DestroyWindow) DestroyWindow;
  decltype(&SDL_HideWindow) HideWindow;
  decltype(&SDL_SetWindowTitle) SetWindowTitle;
  decltype(&SDL_CreateRenderer) CreateRenderer;
  decltype(&SDL_DestroyRenderer) DestroyRenderer;
  decltype(&SDL_GetRendererOutputSize) GetRendererOutputSize;
  decltype(&SDL_RenderClear) RenderClear;
  decltype(&SDL_RenderCopy) RenderCopy;
  decltype(&SDL_RenderPresent) RenderPresent;
  decltype(&SDL_RenderReadPixels) RenderReadPixels;
  decltype(&SDL_CreateTexture) CreateTexture;
  decltype(&SDL_DestroyTexture) DestroyTexture;
  decltype(&SDL_UpdateTexture) UpdateTexture;
  decltype(&SDL_PollEvent) PollEvent;
};

/// Loads SDL2 (libSDL2-2.0.so.0, Debian's libsdl2-2.0-0) on the first call; null, with the reason in
/// `why`, when the library or one of its functions is missing.
const SdlLibrary* load_sdl_library(std::string& why);

}  // namespace snell::cli
