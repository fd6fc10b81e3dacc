// The stand-ins of distributed.hpp for a build without MPI: one process, rank 0 of 1.
#ifndef SNELL_HAVE_MPI
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

}  // namespace snell::cli::distributed
#endif
