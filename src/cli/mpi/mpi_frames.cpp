// Whole frames over MPI ranks (distributed.hpp, render_frames). Messages, all on MPI_COMM_WORLD, with tags
// apart from the tile queue's (mpi_render.cpp):
//   worker -> 0  kFrameRequest  (no data)       asks for a frame
//   0 -> worker  kFrameAssign   int index, or -1 the frame, or "no more"
//   worker -> 0  kFrameDone     int exit code   the worker has stopped
// Each rank writes the frames it renders (the output folder is shared, as the scene file is), so no pixels
// travel. Rank 0 serves the queue on a second thread, polling like the tile queue, and renders frames on its
// main thread; in this mode frames render without MPI (render_alone), so only the queue thread calls MPI.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

#include "cli/distributed.hpp"
#include "cli/mpi/mpi_transport.hpp"

namespace snell::cli::distributed {

namespace {

enum FrameTag : int { kFrameRequest = 11, kFrameAssign = 12, kFrameDone = 13 };
constexpr int kNoMoreFrames = -1;

int work_frames(const std::function<int(int)>& render_frame) {
  int code = 0;
  while (code == 0) {
    mpi::send_empty(0, kFrameRequest);
    int index = kNoMoreFrames;
    mpi::recv(&index, 1, 0, kFrameAssign);
    if (index == kNoMoreFrames) break;
    code = render_frame(index);
  }
  mpi::send(&code, 1, 0, kFrameDone);
  return code;
}

int lead_frames(int count, const std::atomic<bool>* cancel, const std::function<int(int)>& render_frame) {
  std::mutex queue_mutex;
  int next = 0;
  bool closed = false;  // no frame is handed out after an interruption
  auto take = [&]() -> int {
    std::lock_guard lock(queue_mutex);
    if (closed || (cancel && cancel->load()) || next >= count) return kNoMoreFrames;
    return next++;
  };
  auto close = [&] {
    std::lock_guard lock(queue_mutex);
    closed = true;
  };

  int worst = 0;
  std::thread queue([&] {
    const int workers = size() - 1;
    for (int done = 0; done < workers;) {
      const mpi::Waiting message = mpi::probe_any();
      if (!message.ready) {
        std::this_thread::sleep_for(std::chrono::microseconds(500));
        continue;
      }
      const int from = message.from;
      if (message.tag == kFrameRequest) {
        mpi::recv_empty(from, kFrameRequest);
        const int index = take();
        mpi::send(&index, 1, from, kFrameAssign);
      } else if (message.tag == kFrameDone) {
        int code = 0;
        mpi::recv(&code, 1, from, kFrameDone);
        if (code != 0) close();
        std::lock_guard lock(queue_mutex);
        worst = std::max(worst, code);
        ++done;
      } else {
        mpi::recv_empty(from, message.tag);
      }
    }
  });

  int own = 0;
  for (int index = take(); index != kNoMoreFrames; index = take()) {
    own = render_frame(index);
    if (own != 0) {
      close();
      break;
    }
  }
  queue.join();
  return std::max(worst, own);
}

}  // namespace

int render_frames(int count, const std::atomic<bool>* cancel, const std::function<int(int)>& render_frame) {
  return rank() == 0 ? lead_frames(count, cancel, render_frame) : work_frames(render_frame);
}

int broadcast_from_lead(int value) {
  if (size() > 1) mpi::api().broadcast(&value, 1, kSnellMpiInt, 0);
  return value;
}

void abort_all(int code) {
  // No MPI_Abort: called from a render thread while rank 0's frame queue may be inside MPI on another (the
  // library is initialised MPI_THREAD_SERIALIZED), it crashed now and then (exit 139 in a loaded ctest run).
  // A rank that exits before MPI_Finalize makes mpirun end the job with that rank's exit code.
  if (size() > 1) {
    std::fflush(nullptr);
    std::_Exit(code);
  }
  std::exit(code);
}

}  // namespace snell::cli::distributed
