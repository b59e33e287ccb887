// Speed against error for lesson 03: the recursion depth of the hall of mirrors from 0 to 8,
// each against a deep reference render (16 bounces). The error is the RMS colour difference
// over the mirror pixels (the reference's final stencil marks them). The time is the mean
// and the fastest frame, with reflection culling on and off; the plot shows the fastest,
// which another process on the machine disturbs least. The scene renderings come from the
// lesson's own count in --stats.
//
//   recursive_mirrors_sweep OUT [--quick] [--check]
//
// writes OUT.csv (tests/sweeps/plot_sweeps.py draws its plot). --quick renders fewer frames
// per timing; --check exits 1 unless the counts are 1 + r with culling and 1 + 2r without, and
// the error falls with depth (never rising by more than rounding) to under a quarter of
// depth 0's.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "gl/image.h"
#include "sweep_support.h"

using namespace stencil;
namespace fs = std::filesystem;

namespace {

const std::string kSize = "640x480";
constexpr int kMaxDepth = 8, kReferenceDepth = 16;

struct Row {
  int depth = 0;
  double frameMs = 0, frameMsNoCulling = 0, rms = 0, maxError = 0;
  double fastestMs = 0, fastestMsNoCulling = 0;  // the fastest frame: less sensitive to other load
  long long renderings = 0, renderingsNoCulling = 0, drawCalls = 0, triangles = 0;
  std::size_t wrongPixels = 0;  // mirror pixels off by more than 5/255 in some channel
};

void run(const std::string& args) {
  runOrExit("recursive_mirrors_sweep",
            std::string(LESSON_03) + " --headless --quiet --size " + kSize + " " + args);
}

std::string depthArgs(int depth) {
  return "--variant hall --time 1 --set depth=" + std::to_string(depth);
}

}  // namespace

int main(int argc, char** argv) {
  int exitCode = 0;
  const auto commandLine = parseSweepCommandLine("recursive_mirrors_sweep", argc, argv, exitCode);
  if (!commandLine) return exitCode;
  const fs::path out = commandLine->out, work = commandLine->work;
  const bool quick = commandLine->quick, check = commandLine->check;

  std::cerr << "sweep: reference at depth " << kReferenceDepth << "\n";
  run(depthArgs(kReferenceDepth) + " --out " + (work / "reference.png").string() + " --stencil-out " +
      (work / "reference-stencil.png").string());
  const Image reference = readPng(work / "reference.png", 4);
  const Image mirror = readPng(work / "reference-stencil.raw.png", 1);

  const std::string frames = quick ? "3" : "31";
  std::vector<Row> rows;
  for (int depth = 0; depth <= kMaxDepth; ++depth) {
    Row row;
    row.depth = depth;
    const fs::path image = work / "render.png", stats = work / "stats.json";
    run(depthArgs(depth) + " --out " + image.string());
    const Image got = readPng(image, 4);
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < mirror.pixels.size(); ++i) {
      if (mirror.pixels[i] == 0) continue;
      int worst = 0;
      for (int c = 0; c < 3; ++c) {
        const int d = std::abs(int(got.pixels[4 * i + c]) - int(reference.pixels[4 * i + c]));
        sum += double(d) * d;
        worst = std::max(worst, d);
      }
      ++n;
      row.wrongPixels += worst > 5;
      row.maxError = std::max(row.maxError, double(worst));
    }
    row.rms = std::sqrt(sum / (3.0 * double(n)));

    run(depthArgs(depth) + " --stats --frames " + frames + " > " + stats.string());
    LessonStats json = LessonStats::read(stats);
    row.frameMs = json.frameMs("mean");
    row.fastestMs = json.frameMs("min");
    row.renderings = json.count("scene_renderings");
    row.drawCalls = json.total("draw_calls");
    row.triangles = json.total("triangles");
    run(depthArgs(depth) + " --set culling=0 --stats --frames " + frames + " > " + stats.string());
    json = LessonStats::read(stats);
    row.frameMsNoCulling = json.frameMs("mean");
    row.fastestMsNoCulling = json.frameMs("min");
    row.renderingsNoCulling = json.count("scene_renderings");
    std::fprintf(stderr,
                 "sweep: depth %d  %3lld renderings %7.2f ms  (no culling %3lld, %7.2f ms)  rms %6.2f\n",
                 depth, row.renderings, row.frameMs, row.renderingsNoCulling, row.frameMsNoCulling, row.rms);
    rows.push_back(row);
  }

  std::ofstream csv(out.string() + ".csv");
  csv << "depth,scene_renderings,frame_ms,fastest_frame_ms,scene_renderings_no_culling,frame_ms_no_culling,"
         "fastest_frame_ms_no_culling,rms_error,max_error,wrong_pixels,draw_calls,triangles\n";
  for (const Row& r : rows)
    csv << r.depth << "," << r.renderings << "," << r.frameMs << "," << r.fastestMs << ","
        << r.renderingsNoCulling << "," << r.frameMsNoCulling << "," << r.fastestMsNoCulling << "," << r.rms
        << "," << r.maxError << "," << r.wrongPixels << "," << r.drawCalls << "," << r.triangles << "\n";
  fs::remove_all(work);
  std::cerr << "sweep: wrote " << out.string() << ".csv\n";

  if (!check) return 0;
  bool ok = true;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    if (r.renderings != 1 + r.depth || r.renderingsNoCulling != 1 + 2 * r.depth) {
      std::cerr << "sweep check FAILED: depth " << r.depth << " rendered " << r.renderings
                << " scenes with culling, " << r.renderingsNoCulling << " without\n";
      ok = false;
    }
    if (i > 0 && r.rms > rows[i - 1].rms + 0.05) {
      std::cerr << "sweep check FAILED: the error rose from depth " << r.depth - 1 << " to " << r.depth
                << "\n";
      ok = false;
    }
  }
  if (!(rows.back().rms < 0.25 * rows.front().rms)) {
    std::cerr << "sweep check FAILED: depth " << kMaxDepth
              << " is not much closer to the reference than depth 0\n";
    ok = false;
  }
  if (ok)
    std::cerr << "sweep check ok: 1 + r renderings with culling, 1 + 2r without; the error falls from "
              << rows.front().rms << " to " << rows.back().rms << "\n";
  return ok ? 0 : 1;
}
