// Whole frames over MPI ranks (distributed.hpp, render_frames). Messages, all on MPI_COMM_WORLD, with tags
// apart from the tile queue's (mpi_render.cpp):
//   worker -> 0  kFrameRequest  (no data)       asks for a frame
//   0 -> worker  kFrameAssign   int index, or -1 the frame, or "no more"
//   worker -> 0  kFrameDone     int exit code   the worker has stopped
// Each rank writes the frames it renders (the output folder is shared, as the scene file is), so no pixels
// travel. Rank 0 serves the queue on a second thread, polling like the tile queue, and renders frames on its
// main thread; in this mode frames render without MPI (render_alone), so only the queue thread calls MPI.
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <thread>

#include "cli/distributed.hpp"

namespace snell::cli::distributed {

namespace {

enum FrameTag : int { kFrameRequest = 11, kFrameAssign = 12, kFrameDone = 13 };
constexpr int kNoMoreFrames = -1;

int work_frames(const std::function<int(int)>& render_frame) {
  int code = 0;
  while (code == 0) {
    MPI_Send(nullptr, 0, MPI_INT, 0, kFrameRequest, MPI_COMM_WORLD);
    int index = kNoMoreFrames;
    MPI_Recv(&index, 1, MPI_INT, 0, kFrameAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (index == kNoMoreFrames) break;
    code = render_frame(index);
  }
  MPI_Send(&code, 1, MPI_INT, 0, kFrameDone, MPI_COMM_WORLD);
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
      int ready = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &ready, &status);
      if (!ready) {
        std::this_thread::sleep_for(std::chrono::microseconds(500));
        continue;
      }
      const int from = status.MPI_SOURCE;
      if (status.MPI_TAG == kFrameRequest) {
        MPI_Recv(nullptr, 0, MPI_INT, from, kFrameRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        const int index = take();
        MPI_Send(&index, 1, MPI_INT, from, kFrameAssign, MPI_COMM_WORLD);
      } else if (status.MPI_TAG == kFrameDone) {
        int code = 0;
        MPI_Recv(&code, 1, MPI_INT, from, kFrameDone, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (code != 0) close();
        std::lock_guard lock(queue_mutex);
        worst = std::max(worst, code);
        ++done;
      } else {
        MPI_Recv(nullptr, 0, MPI_BYTE, from, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
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
  if (size() > 1) MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value;
}

void abort_all(int code) {
  if (size() > 1) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

}  // namespace snell::cli::distributed
