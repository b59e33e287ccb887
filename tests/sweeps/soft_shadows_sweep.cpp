// Speed against error for lesson 10: the visible fraction from N point lights (N = 1, 2, 4, ...,
// 256) on a grid, jittered and Halton, over a rectangle and a disk light, and progressive rounds
// of 16, against the exact visible fraction (the lesson's reference variant, analytic). Error in
// levels of 255 (the red channel of the visibility picture): RMS and max over the penumbra's
// pixels (the reference's grey ground strictly between 0 and 255) and over the whole image; time per frame
// and its ratio to N = 1 (the fastest of the frames after the first: the least noisy). Also the 8-bit and
// 16-bit blends against RGBA32F, in levels lost.
//
//   soft_shadows_sweep OUT [--quick] [--check]
//
// writes OUT.csv (one row per run) and OUT.summary.csv (slopes of error against N, blends);
// tests/sweeps/plot_sweeps.py draws OUT.svg from OUT.csv. --quick sweeps the rectangle to N = 64 only;
// --check exits 1 unless the penumbra error falls with N for jittered and Halton samples, and each run's
// errors lie within what the committed sweep (docs/sweeps/10-soft-shadows.csv) measured for its N: the soft
// result is as good as the sweep predicts.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "gl/image.h"
#include "sweep_support.h"

using namespace stencil;
namespace fs = std::filesystem;

namespace {

const std::string kSize = "320x240";
const char* kPatterns[] = {"grid", "jittered", "halton"};

struct Row {
  std::string shape, pattern;  // pattern: grid, jittered, halton, or <pattern>-progressive
  int lights = 0, rounds = 1;
  double penumbraRms = 0, penumbraMax = 0, imageRms = 0, imageMax = 0, frameMs = 0, ratio = 0;
  long long penumbraPixels = 0;
  long long triangles = 0, fragments = 0;  // per frame, every pass: noise-free cost
  int samples() const { return lights * rounds; }
};

void run(const std::string& args) {
  runOrExit("soft_shadows_sweep",
            std::string(LESSON_10) + " --headless --quiet --size " + kSize + " " + args);
}

void measure(Row& row, const Image& got, const Image& ref) {
  double sumP = 0, sumI = 0;
  long long nP = 0, nI = 0;
  for (std::size_t i = 0; i < ref.pixels.size() / 4; ++i) {
    const int r = ref.pixels[4 * i];
    const double d = std::abs(double(got.pixels[4 * i]) - r);
    sumI += d * d;
    ++nI;
    row.imageMax = std::max(row.imageMax, d);
    // The penumbra: ground (grey) pixels the reference gives strictly between 0 and 255; the
    // background's clear colour is not grey.
    if (r == 0 || r == 255 || ref.pixels[4 * i + 1] != r || ref.pixels[4 * i + 2] != r) continue;
    sumP += d * d;
    ++nP;
    row.penumbraMax = std::max(row.penumbraMax, d);
  }
  row.penumbraRms = std::sqrt(sumP / double(std::max(1LL, nP)));
  row.imageRms = std::sqrt(sumI / double(std::max(1LL, nI)));
  row.penumbraPixels = nP;
}

// Least-squares slope of log2(RMS) against log2(samples), over the rows from 4 samples on.
double slope(const std::vector<const Row*>& rows) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (const Row* r : rows) {
    if (r->samples() < 4 || r->penumbraRms <= 0) continue;
    const double x = std::log2(r->samples()), y = std::log2(r->penumbraRms);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
  }
  return n < 2 ? 0.0 : (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

std::string seriesName(const Row& r) {
  return r.shape + " " + r.pattern;
}

// Levels lost by a blend: the largest difference and the pixels more than one level off, against
// the same variant in RGBA32F.
std::string blendLoss(const fs::path& work, const std::string& label, const std::string& args, int format) {
  const fs::path a = work / "blend32.png", b = work / "blend.png";
  run(args + " --set float=1 --out " + a.string());
  run(args + " --set float=" + std::to_string(format) + " --out " + b.string());
  const Image x = readPng(a, 4), y = readPng(b, 4);
  int largest = 0;
  long long over = 0;
  for (std::size_t i = 0; i < x.pixels.size() / 4; ++i) {
    int worst = 0;
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(int(x.pixels[4 * i + c]) - int(y.pixels[4 * i + c])));
    largest = std::max(largest, worst);
    over += worst > 1;
  }
  std::fprintf(stderr, "sweep: %s: largest difference %d levels, %lld pixels more than one level off\n",
               label.c_str(), largest, over);
  return "blend," + label + "," + std::to_string(largest) + "," + std::to_string(over);
}

}  // namespace

int main(int argc, char** argv) {
  int exitCode = 0;
  const auto commandLine = parseSweepCommandLine("soft_shadows_sweep", argc, argv, exitCode);
  if (!commandLine) return exitCode;
  const fs::path out = commandLine->out, work = commandLine->work;
  const bool quick = commandLine->quick, check = commandLine->check;
  const std::string frames = quick ? "2" : "6";

  std::vector<Row> rows;
  for (int disk = 0; disk <= (quick ? 0 : 1); ++disk) {
    const std::string shape = disk ? "disk" : "rectangle", shapeArgs = " --set disk=" + std::to_string(disk);
    const fs::path refPath = work / "reference.png";
    run("--variant reference" + shapeArgs + " --out " + refPath.string());
    const Image ref = readPng(refPath, 4);
    for (int p = 0; p < 3; ++p) {
      double oneMs = 0;
      for (int n = 1; n <= (quick ? 64 : 256); n *= 2) {
        if (quick && n != 1 && n != 4 && n != 16 && n != 64) continue;
        Row row{shape, kPatterns[p], n};
        const fs::path image = work / "render.png", stats = work / "stats.json";
        run("--set visibility=1" + shapeArgs + " --set pattern=" + std::to_string(p) +
            " --set lights=" + std::to_string(n) + " --frames " + frames + " --stats --out " +
            image.string() + " > " + stats.string());
        measure(row, readPng(image, 4), ref);
        const LessonStats json = LessonStats::read(stats);
        row.frameMs = json.frameMs("min");
        row.triangles = json.total("triangles");
        row.fragments = json.total("samples_passed");
        if (n == 1) oneMs = row.frameMs;
        row.ratio = row.frameMs / oneMs;
        std::fprintf(
            stderr,
            "sweep: %-9s %-8s N=%3d  penumbra rms %6.2f max %5.1f  image rms %5.2f  %8.2f ms (x%.1f)\n",
            shape.c_str(), kPatterns[p], n, row.penumbraRms, row.penumbraMax, row.imageRms, row.frameMs,
            row.ratio);
        rows.push_back(row);
      }
    }
    // Progressive: 16 lights a round, each round fresh samples, the running average shown.
    for (int p = 1; p < 3; ++p)
      for (int rounds = 1; rounds <= (quick ? 4 : 16); rounds *= 2) {
        Row row{shape, std::string(kPatterns[p]) + "-progressive", 16, rounds};
        const fs::path image = work / "render.png", stats = work / "stats.json";
        run("--set visibility=1 --set progressive=1" + shapeArgs + " --set pattern=" + std::to_string(p) +
            " --set lights=16 --frames " + std::to_string(rounds) + " --stats --out " + image.string() +
            " > " + stats.string());
        measure(row, readPng(image, 4), ref);
        row.frameMs = LessonStats::read(stats).frameMs("min");
        std::fprintf(stderr, "sweep: %-9s %-20s %3d samples  penumbra rms %6.2f\n", shape.c_str(),
                     row.pattern.c_str(), row.samples(), row.penumbraRms);
        rows.push_back(row);
      }
  }

  std::map<std::string, double> slopes;
  for (const Row& r : rows) {
    if (slopes.count(seriesName(r))) continue;
    std::vector<const Row*> series;
    for (const Row& s : rows)
      if (seriesName(s) == seriesName(r)) series.push_back(&s);
    slopes[seriesName(r)] = slope(series);
    std::fprintf(stderr, "sweep: %s: penumbra RMS error ~ samples^%.2f\n", seriesName(r).c_str(),
                 slopes[seriesName(r)]);
  }
  std::vector<std::string> blends;
  if (!quick) {
    blends.push_back(blendLoss(work, "kilgard-8 in RGBA8", "--variant kilgard-8", 0));
    blends.push_back(blendLoss(work, "256 lights in RGBA8", "--variant many", 0));
    blends.push_back(blendLoss(work, "256 lights in RGBA16F", "--variant many", 2));
  }

  {
    std::ofstream csv(out.string() + ".csv");
    csv << "shape,pattern,lights,rounds,samples,penumbra_rms,penumbra_max,image_rms,image_max,penumbra_"
           "pixels,frame_ms,"
           "ratio_to_n1,triangles,fragments\n";
    for (const Row& r : rows)
      csv << r.shape << "," << r.pattern << "," << r.lights << "," << r.rounds << "," << r.samples() << ","
          << r.penumbraRms << "," << r.penumbraMax << "," << r.imageRms << "," << r.imageMax << ","
          << r.penumbraPixels << "," << r.frameMs << "," << r.ratio << "," << r.triangles << ","
          << r.fragments << "\n";
    std::ofstream summary(out.string() + ".summary.csv");
    summary << "kind,what,value,pixels_over_one_level\n";
    for (const auto& [name, s] : slopes) summary << "slope," << name << "," << s << ",\n";
    for (const std::string& b : blends) summary << b << "\n";
  }
  fs::remove_all(work);
  std::cerr << "sweep: wrote " << out.string() << ".csv and .summary.csv\n";
  if (!check) return 0;

  bool ok = true;
  // The error falls with the samples for jittered and Halton (slope below -0.4).
  for (const char* s : {"rectangle jittered", "rectangle halton"})
    if (slopes[s] > -0.4) {
      std::cerr << "sweep check FAILED: " << s << " slope " << slopes[s] << "\n";
      ok = false;
    }
  // Each run within what the committed sweep measured for its N (a quarter more, or half a level).
  std::ifstream committed(COMMITTED_CSV);
  std::string line;
  std::getline(committed, line);
  std::map<std::string, double> predicted;
  while (std::getline(committed, line)) {
    std::stringstream fields(line);
    std::vector<std::string> f;
    for (std::string v; std::getline(fields, v, ',');) f.push_back(v);
    if (f.size() >= 6) predicted[f[0] + " " + f[1] + " " + f[2] + " " + f[3]] = std::stod(f[5]);
  }
  if (predicted.empty()) {
    std::cerr << "sweep check FAILED: no committed sweep at " << COMMITTED_CSV << "\n";
    return 1;
  }
  for (const Row& r : rows) {
    const auto it = predicted.find(r.shape + " " + r.pattern + " " + std::to_string(r.lights) + " " +
                                   std::to_string(r.rounds));
    if (it == predicted.end()) continue;
    if (r.penumbraRms > std::max(1.25 * it->second, it->second + 0.5)) {
      std::fprintf(stderr,
                   "sweep check FAILED: %s N=%d rounds %d: penumbra rms %.2f, the sweep predicts %.2f\n",
                   seriesName(r).c_str(), r.lights, r.rounds, r.penumbraRms, it->second);
      ok = false;
    }
  }
  std::cerr << (ok ? "sweep check ok\n" : "");
  return ok ? 0 : 1;
}
