// The SDL2 render window (preview_window.hpp). SDL's video calls must all come from one thread, and the
// render's main thread is busy rendering, so the window has a thread of its own: it owns every SDL object,
// polls events and redraws about 30 times a second from an 8-bit RGB copy of the image that the render
// threads fill tile by tile under a mutex.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstdlib>
#include <future>
#include <mutex>
#include <thread>
#include <vector>

#include "cli/preview/preview_window.hpp"
#include "cli/preview/sdl_library.hpp"
#include "snell/io/png_writer.hpp"

namespace snell::cli {

namespace {

using Clock = std::chrono::steady_clock;

/// Largest window before the image is shown scaled down (it still keeps the image's aspect).
constexpr int kMaxWindowWidth = 1600;
constexpr int kMaxWindowHeight = 1000;
constexpr auto kFramePeriod = std::chrono::milliseconds(33);
/// Largest image shown: SDL's software renderer limits textures to 16384 pixels a side, and the window's
/// 8-bit copy of a larger image would cost gigabytes.
constexpr int kMaxImageSide = 16384;

class SdlPreviewWindow final : public PreviewWindow {
 public:
  SdlPreviewWindow(const SdlLibrary& sdl, int width, int height, std::string title,
                   const io::Encoding& encoding)
      : sdl_(sdl),
        width_(width),
        height_(height),
        title_(std::move(title)),
        encoding_(encoding),
        pixels_(static_cast<size_t>(width) * height * 3, 0),
        start_(Clock::now()) {}

  ~SdlPreviewWindow() override {
    if (thread_.joinable()) finish({}, false, nullptr);
  }

  /// Starts the window thread; false (with the reason) when SDL cannot open a window.
  bool start(std::string& why) {
    std::promise<std::string> started;
    std::future<std::string> result = started.get_future();
    thread_ = std::thread([this, &started] { run(started); });
    why = result.get();
    if (why.empty()) return true;
    thread_.join();
    return false;
  }

  void show_tile(const render::Tile& tile, const io::Image& image) override {
    std::lock_guard lock(mutex_);
    const render::PixelRect& r = tile.rect;
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x)
        for (int c = 0; c < 3; ++c) {
          const size_t i = (static_cast<size_t>(y) * width_ + x) * 3 + c;
          // The PNG writer's quantisation (image_file.cpp), so the window holds the file's bytes.
          pixels_[i] = static_cast<uint8_t>(std::lround(encoding_.encode(image.rgb[i]) * 255.0));
        }
    dirty_ = true;
  }

  void set_progress(double fraction) override {
    std::lock_guard lock(mutex_);
    fraction_ = fraction;
  }

  void finish(const std::filesystem::path& snapshot, bool wait_for_key,
              const std::atomic<bool>* stop_waiting) override {
    {
      std::lock_guard lock(mutex_);
      snapshot_ = snapshot;
      wait_for_key_ = wait_for_key;
      stop_waiting_ = stop_waiting;
      finishing_ = true;
      dirty_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }

 private:
  void run(std::promise<std::string>& started) {
    // The window is a plain framebuffer: no OpenGL (loading Mesa costs about a second and needs no GPU here).
    sdl_.SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
    sdl_.SetHint(SDL_HINT_RENDER_DRIVER, "software");
    // snell's own SIGINT/SIGTERM handlers (interrupt, resume file) must stay in place.
    sdl_.SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    if (sdl_.Init(SDL_INIT_VIDEO) != 0) {
      started.set_value(fmt::format("cannot start SDL video: {}", sdl_.GetError()));
      return;
    }
    const double scale =
        std::min({1.0, double(kMaxWindowWidth) / width_, double(kMaxWindowHeight) / height_});
    const int window_w = std::max(1, static_cast<int>(width_ * scale));
    const int window_h = std::max(1, static_cast<int>(height_ * scale));
    SDL_Window* window = sdl_.CreateWindow(title_.c_str(), SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                                           window_w, window_h, SDL_WINDOW_SHOWN);
    // The software renderer: no GPU needed, and its read-back returns exactly the bytes uploaded.
    SDL_Renderer* renderer = window ? sdl_.CreateRenderer(window, -1, SDL_RENDERER_SOFTWARE) : nullptr;
    SDL_Texture* texture = renderer ? sdl_.CreateTexture(renderer, SDL_PIXELFORMAT_RGB24,
                                                         SDL_TEXTUREACCESS_STREAMING, width_, height_)
                                    : nullptr;
    if (!texture) {
      started.set_value(fmt::format("cannot open a window: {}", sdl_.GetError()));
      if (renderer) sdl_.DestroyRenderer(renderer);
      if (window) sdl_.DestroyWindow(window);
      sdl_.Quit();
      return;
    }
    started.set_value({});
    loop(window, renderer, texture);
    sdl_.DestroyTexture(texture);
    sdl_.DestroyRenderer(renderer);
    sdl_.DestroyWindow(window);
    sdl_.Quit();
  }

  void loop(SDL_Window* window, SDL_Renderer* renderer, SDL_Texture* texture) {
    bool key_pressed = false;
    bool closed = false;
    std::string shown_title;
    for (;;) {
      for (SDL_Event e; sdl_.PollEvent(&e);) {
        if (e.type == SDL_KEYDOWN) key_pressed = true;
        if (e.type == SDL_QUIT || (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_CLOSE))
          closed = true;
      }
      std::unique_lock lock(mutex_);
      const bool finishing = finishing_;
      if (dirty_) {
        sdl_.UpdateTexture(texture, nullptr, pixels_.data(), width_ * 3);
        dirty_ = false;
      }
      const std::string title = title_line(finishing);
      lock.unlock();
      if (title != shown_title) sdl_.SetWindowTitle(window, title.c_str());
      shown_title = title;
      sdl_.RenderClear(renderer);
      sdl_.RenderCopy(renderer, texture, nullptr, nullptr);
      if (finishing && !snapshot_taken_) {
        write_snapshot(renderer);
        snapshot_taken_ = true;
      }
      sdl_.RenderPresent(renderer);
      // A window the user closed stays closed for the rest of the render; nothing waits for it then.
      if (finishing && (!wait_for_key_ || key_pressed || closed || (stop_waiting_ && *stop_waiting_))) return;
      if (closed && !finishing) sdl_.HideWindow(window);
      lock.lock();
      wake_.wait_for(lock, kFramePeriod, [this, finishing] { return finishing_ != finishing; });
    }
  }

  /// "snell: scene.pov  42%  12 s left", then "done in 3.4 s" (and how to close it under +P).
  std::string title_line(bool finishing) const {
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    if (finishing)
      return fmt::format("{}  done in {:.1f} s{}", title_, elapsed,
                         wait_for_key_ ? "  (press a key to close)" : "");
    if (fraction_ <= 0) return fmt::format("{}  0%", title_);
    const double left = elapsed * (1 - fraction_) / fraction_;
    return fmt::format("{}  {:.0f}%  {:.0f} s left", title_, fraction_ * 100, left);
  }

  /// Reads the window's pixels back from the renderer (before present, while they are defined) as PNG.
  void write_snapshot(SDL_Renderer* renderer) const {
    if (snapshot_.empty()) return;
    int w = 0, h = 0;
    sdl_.GetRendererOutputSize(renderer, &w, &h);
    std::vector<uint8_t> shot(static_cast<size_t>(w) * h * 3);
    std::string why;
    if (sdl_.RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_RGB24, shot.data(), w * 3) != 0)
      why = sdl_.GetError();
    else
      why = io::write_png(snapshot_, w, h, 3, 8, shot.data(), true);
    if (!why.empty()) fmt::print(stderr, "snell: warning: cannot write the window snapshot: {}\n", why);
  }

  const SdlLibrary& sdl_;
  const int width_, height_;
  const std::string title_;
  const io::Encoding encoding_;
  std::thread thread_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<uint8_t> pixels_;
  bool dirty_ = false;
  bool finishing_ = false;
  bool wait_for_key_ = false;
  const std::atomic<bool>* stop_waiting_ = nullptr;
  bool snapshot_taken_ = false;
  double fraction_ = 0;
  std::filesystem::path snapshot_;
  const Clock::time_point start_;
};

bool has_display() {
  for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"})
    if (const char* v = std::getenv(name); v && *v) return true;
  return false;
}

}  // namespace

std::unique_ptr<PreviewWindow> open_preview_window(int width, int height, const std::string& title,
                                                   const io::Encoding& encoding, std::string& why) {
  if (!has_display()) {
    why = "no display ($DISPLAY is not set)";
    return nullptr;
  }
  if (width > kMaxImageSide || height > kMaxImageSide) {
    why = fmt::format("the image is larger than {} pixels a side", kMaxImageSide);
    return nullptr;
  }
  const SdlLibrary* sdl = load_sdl_library(why);
  if (!sdl) return nullptr;
  auto window = std::make_unique<SdlPreviewWindow>(*sdl, width, height, title, encoding);
  if (!window->start(why)) return nullptr;
  return window;
}

}  // namespace snell::cli
