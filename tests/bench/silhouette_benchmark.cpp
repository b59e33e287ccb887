// Silhouette extraction against a plain memory scan of the same data (Google Benchmark).
//
// silhouette: facesLight (every triangle's three indices and positions: does it face the
// light?) then silhouetteEdges (every edge of the prepared caster's adjacency: do its two faces
// disagree?), on welded spheres and tori of about 1k to 1M triangles. scan: the same arrays
// (indices, positions, edges) summed, nothing else: how fast the machine can merely read what
// the extraction reads. The ratio says how far from memory-bound the extraction is. The two
// halves are timed apart too (faces: facesLight alone; edges: silhouetteEdges on its result).
//
//   silhouette_benchmark [--quick] [--table FILE.md] [benchmark flags]
//
// --quick: the three smallest sizes only, and a check that every silhouette is a set of closed
// loops (each vertex leaves it as often as it enters it); exit 1 if not. --table writes the
// results as a Markdown table (triangles, ns per triangle, GB/s, ratio to the scan).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "geometry/scene.h"
#include "geometry/shadow_volume.h"
#include "geometry/shapes.h"

using namespace stencil;

namespace {

struct Size {
  const char* name;
  int sphereSlices, sphereStacks;  // 2 * slices * (stacks - 1) triangles
  int torusMajor, torusMinor;      // 2 * major * minor triangles
};
constexpr Size sizes[] = {
    {"1k", 32, 17, 32, 16},      {"4k", 64, 33, 64, 32},       {"16k", 128, 65, 128, 64},
    {"64k", 256, 129, 256, 128}, {"256k", 512, 257, 512, 256}, {"1M", 1024, 513, 1024, 512},
};

// Built once per shape and size, outside the timed loops.
const PreparedCaster& caster(const std::string& shape, const Size& size) {
  static std::map<std::string, std::unique_ptr<PreparedCaster>> cache;
  auto& slot = cache[shape + size.name];
  if (!slot) {
    const Mesh mesh = shape == "sphere" ? makeSphere(1.0f, size.sphereSlices, size.sphereStacks)
                                        : makeTorus(1.0f, 0.3f, size.torusMajor, size.torusMinor);
    slot = std::make_unique<PreparedCaster>(prepareCaster(mesh));
  }
  return *slot;
}

// What both benchmarks read, in bytes: indices and positions (facesLight), edges (silhouetteEdges).
std::int64_t bytesRead(const PreparedCaster& c) {
  return static_cast<std::int64_t>(c.mesh.indices.size() * sizeof(std::uint32_t) +
                                   c.mesh.positions.size() * sizeof(glm::vec3) +
                                   c.adjacency.edges.size() * sizeof(Edge));
}

const glm::vec4 light(3.0f, 4.0f, 5.0f, 1.0f);

void silhouette(benchmark::State& state, const std::string& shape, const Size& size) {
  const PreparedCaster& c = caster(shape, size);
  std::size_t edges = 0;
  for (auto _ : state) {
    const std::vector<bool> lit = facesLight(c.mesh, light);
    const std::vector<SilhouetteEdge> silhouette = silhouetteEdges(c.adjacency, lit);
    edges = silhouette.size();
    benchmark::DoNotOptimize(silhouette.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.mesh.triangleCount()));
  state.SetBytesProcessed(state.iterations() * bytesRead(c));
  state.counters["triangles"] = static_cast<double>(c.mesh.triangleCount());
  state.counters["silhouette_edges"] = static_cast<double>(edges);
}

void faces(benchmark::State& state, const std::string& shape, const Size& size) {
  const PreparedCaster& c = caster(shape, size);
  for (auto _ : state) {
    std::vector<bool> lit = facesLight(c.mesh, light);  // not const: DoNotOptimize takes a mutable lvalue
    benchmark::DoNotOptimize(lit);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.mesh.triangleCount()));
  state.counters["triangles"] = static_cast<double>(c.mesh.triangleCount());
}

void edges(benchmark::State& state, const std::string& shape, const Size& size) {
  const PreparedCaster& c = caster(shape, size);
  const std::vector<bool> lit = facesLight(c.mesh, light);
  for (auto _ : state) {
    const std::vector<SilhouetteEdge> silhouette = silhouetteEdges(c.adjacency, lit);
    benchmark::DoNotOptimize(silhouette.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.mesh.triangleCount()));
  state.counters["triangles"] = static_cast<double>(c.mesh.triangleCount());
}

void scan(benchmark::State& state, const std::string& shape, const Size& size) {
  const PreparedCaster& c = caster(shape, size);
  for (auto _ : state) {
    std::uint32_t indexSum = 0, edgeSum = 0;
    float positionSum = 0.0f;
    for (std::uint32_t i : c.mesh.indices) indexSum += i;
    for (const glm::vec3& p : c.mesh.positions) positionSum += p.x + p.y + p.z;
    for (const Edge& e : c.adjacency.edges)
      edgeSum += e.v0 + e.v1 + static_cast<std::uint32_t>(e.face0) + static_cast<std::uint32_t>(e.face1);
    benchmark::DoNotOptimize(indexSum);
    benchmark::DoNotOptimize(positionSum);
    benchmark::DoNotOptimize(edgeSum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.mesh.triangleCount()));
  state.SetBytesProcessed(state.iterations() * bytesRead(c));
  state.counters["triangles"] = static_cast<double>(c.mesh.triangleCount());
}

// A silhouette of a closed mesh is made of closed loops: every vertex starts as many of its
// directed edges as it ends.
bool closedLoops(const PreparedCaster& c) {
  const std::vector<SilhouetteEdge> edges = silhouetteEdges(c.adjacency, facesLight(c.mesh, light));
  std::vector<int> balance(c.mesh.positions.size(), 0);
  for (const SilhouetteEdge& e : edges) {
    ++balance[e.v0];
    --balance[e.v1];
  }
  for (int b : balance)
    if (b != 0) return false;
  return !edges.empty();
}

// Google Benchmark 1.8 replaced Run::error_occurred with Run::skipped; both are in use (Debian 12
// has 1.7, Debian 13 has 1.9).
template <typename R>
bool failed(const R& run) {
  if constexpr (requires { run.skipped; })
    return static_cast<int>(run.skipped) != 0;
  else
    return run.error_occurred;
}

// Keeps each run's time per iteration for the table.
class TableReporter : public benchmark::ConsoleReporter {
 public:
  struct Row {
    double triangles = 0, bytes = 0, ns = 0, edges = 0;
  };
  std::map<std::string, Row> rows;  // by name: "silhouette/sphere/1k"

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (failed(run) || run.run_type != Run::RT_Iteration) continue;
      Row& row = rows[run.benchmark_name()];
      row.ns = run.GetAdjustedCPUTime();  // nanoseconds; CPU time, as the machine may be shared
      row.triangles = run.counters.at("triangles").value;
      if (run.counters.count("silhouette_edges")) row.edges = run.counters.at("silhouette_edges").value;
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

void writeTable(const TableReporter& reporter, const std::string& file) {
  std::ofstream out(file);
  out << "# Silhouette extraction against a memory scan\n\n"
      << "`facesLight` + `silhouetteEdges` (common/geometry/shadow_volume.h) on welded spheres and tori,\n"
      << "a point light at (3, 4, 5), against summing the same arrays (indices, positions, edges).\n"
      << "CPU time per call; GB/s counts the bytes of those arrays once per call. The two halves,\n"
      << "timed apart: facesLight (indices and positions) and silhouetteEdges (edges and the flags).\n"
      << "Written by `cmake --build build --target silhouette-benchmark` (raw figures in\n"
      << "silhouette-extraction.json).\n\n"
      << "| shape | triangles | silhouette edges | silhouette ns/triangle | of which facesLight | of which "
         "silhouetteEdges | silhouette GB/s | scan ns/triangle | scan GB/s | silhouette time / scan time |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const char* shape : {"sphere", "torus"})
    for (const Size& size : sizes) {
      const std::string key = std::string("/") + shape + "/" + size.name;
      const auto s = reporter.rows.find("silhouette" + key), m = reporter.rows.find("scan" + key),
                 f = reporter.rows.find("faces" + key), e = reporter.rows.find("edges" + key);
      if (s == reporter.rows.end() || m == reporter.rows.end() || f == reporter.rows.end() ||
          e == reporter.rows.end())
        continue;
      const double bytes = static_cast<double>(bytesRead(caster(shape, size)));
      char line[256];
      std::snprintf(
          line, sizeof line, "| %s | %.0f | %.0f | %.2f | %.2f | %.2f | %.2f | %.3f | %.2f | %.1f |\n", shape,
          s->second.triangles, s->second.edges, s->second.ns / s->second.triangles,
          f->second.ns / f->second.triangles, e->second.ns / e->second.triangles, bytes / s->second.ns,
          m->second.ns / m->second.triangles, bytes / m->second.ns, s->second.ns / m->second.ns);
      out << line;
    }
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::string table;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--quick")
      quick = true;
    else if (arg == "--table" && i + 1 < argc)
      table = argv[++i];
    else
      rest.push_back(argv[i]);
  }
  int restCount = static_cast<int>(rest.size());
  benchmark::Initialize(&restCount, rest.data());
  if (benchmark::ReportUnrecognizedArguments(restCount, rest.data())) return 2;

  const std::size_t count = quick ? 3 : std::size(sizes);
  for (const char* shape : {"sphere", "torus"})
    for (std::size_t i = 0; i < count; ++i) {
      const Size& size = sizes[i];
      const std::string key = std::string("/") + shape + "/" + size.name;
      benchmark::RegisterBenchmark(("silhouette" + key).c_str(), silhouette, std::string(shape), size);
      benchmark::RegisterBenchmark(("scan" + key).c_str(), scan, std::string(shape), size);
      benchmark::RegisterBenchmark(("faces" + key).c_str(), faces, std::string(shape), size);
      benchmark::RegisterBenchmark(("edges" + key).c_str(), edges, std::string(shape), size);
      if (quick && !closedLoops(caster(shape, size))) {
        std::cerr << shape << " " << size.name << ": the silhouette is not a set of closed loops\n";
        return 1;
      }
    }
  TableReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  if (!table.empty()) writeTable(reporter, table);
  benchmark::Shutdown();
  return 0;
}
