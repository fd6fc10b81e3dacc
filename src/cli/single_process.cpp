// The stand-ins of distributed.hpp for a build without MPI: one process, rank 0 of 1.
#ifndef SNELL_HAVE_MPI
#include <cstdlib>

#include "cli/distributed.hpp"

namespace snell::cli::distributed {

Session::Session(int&, char**&) {}
Session::~Session() = default;
int rank() {
  return 0;
}
int size() {
  return 1;
}
const char* support() {
  return "without MPI";
}

render::RenderStats render(const Job& job, io::Image& image) {
  return render_alone(job, image);
}

int render_frames(int count, const std::atomic<bool>*, const std::function<int(int)>& render_frame) {
  for (int index = 0; index < count; ++index)
    if (const int code = render_frame(index); code != 0) return code;
  return 0;
}

int broadcast_from_lead(int value) {
  return value;
}

void abort_all(int code) {
  std::exit(code);
}

}  // namespace snell::cli::distributed
#endif
