// Headless turntables: one HeadlessSession (the --renderer's renderer), N cameras, one sink.
#include "app/turntable.h"

#include <chrono>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "app/headless.h"
#include "app/headless_session.h"
#include "io/frame_sink.h"
#include "io/terminal_progress.h"

namespace ewa {

void renderTurntable(const Scene& scene, const Options& o) {
  const int count = o.turntable;
  refuseToOverwriteInputs(o.output, o);
  // The sink checks or makes its folder or file first, so a bad path fails before rendering.
  const std::unique_ptr<FrameSink> sink = openFrameSink(o.output, count, o.fps);
  HeadlessSession session(o.backend, o.shaderDir);
  session.setAxes(o.axes);
  const Camera start = initialCamera(scene.volume, o);
  TerminalProgress progress("ewaview: turntable");
  const auto begin = std::chrono::steady_clock::now();
  std::vector<std::string> notes;  // said after the progress line, not through it
  for (int f = 0; f < count; ++f) {
    progress.update(f + 1, count, sink->fileOf(f));
    sink->add(session.render(scene.volume, scene.transferFunction, turntableCamera(start, f, count),
                             o.render, o.width, o.height),
              f);
    if (std::string note = session.takeNote(); !note.empty()) notes.push_back(std::move(note));
  }
  sink->finish();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  char note[96];
  std::snprintf(note, sizeof note, "%d frames in %.1f s", count, s);
  progress.finish(note);
  for (const std::string& line : notes) std::fprintf(stderr, "ewaview: %s\n", line.c_str());
}

}  // namespace ewa
