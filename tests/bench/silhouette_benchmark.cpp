// Silhouette extraction against a plain memory scan of the same data (Google Benchmark).
//
// mesh: facesLight (every triangle's three indices and positions: does it face the light?) then
// possibleSilhouetteEdges (every edge of the prepared caster's adjacency: do its two faces disagree?), on
// welded spheres and tori of about 1k to 1M triangles. prepared: the same edges from a
// SilhouetteCaster (face normals and first corners precomputed once, streamed by the facing pass;
// each edge's two faces read once against one-byte flags). scan: the arrays the mesh version
// reads (indices, positions, edges) summed as 32-bit words, nothing else; scan-prepared: the same
// for the arrays the prepared version streams (the six per-face floats and the edges' faces).
// The ratios say how far from memory-bound each extraction is. The halves are timed apart too
// (faces/edges: the mesh version's two calls; facing/edgepass: the prepared version's), and
// prepare: building the SilhouetteCaster, once per caster.
//
//   silhouette_benchmark [--quick] [--table FILE.md] [--raw FILE.csv] [benchmark flags]
//
// --quick: the three smallest sizes only, and two checks: every silhouette is a set of closed
// loops (each vertex leaves it as often as it enters it), and the prepared version gives the
// mesh version's edges; exit 1 if not. --table writes the results as a Markdown table
// (triangles, ns per triangle, GB/s, ratios to the scans); --raw the CPU time of every repetition
// of every benchmark as CSV.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <glm/trigonometric.hpp>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "geometry/dual_silhouette.h"
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

const SilhouetteCaster& silhouetteCaster(const std::string& shape, const Size& size) {
  static std::map<std::string, std::unique_ptr<SilhouetteCaster>> cache;
  auto& slot = cache[shape + size.name];
  if (!slot) {
    const PreparedCaster& c = caster(shape, size);
    slot = std::make_unique<SilhouetteCaster>(prepareSilhouettes(c.mesh, c.adjacency));
  }
  return *slot;
}

const DualSilhouettes& dualTree(const std::string& shape, const Size& size) {
  static std::map<std::string, std::unique_ptr<DualSilhouettes>> cache;
  auto& slot = cache[shape + size.name];
  if (!slot) slot = std::make_unique<DualSilhouettes>(silhouetteCaster(shape, size));
  return *slot;
}

// The sum of an array's bytes as 32-bit words, four running sums so that the loop is bound by
// loads, not by one addition's latency.
template <typename T>
std::uint32_t sumWords(const std::vector<T>& v) {
  static_assert(sizeof(T) % 4 == 0);
  const std::size_t words = v.size() * sizeof(T) / 4;
  const auto* p = reinterpret_cast<const std::uint32_t*>(v.data());
  std::uint32_t s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  std::size_t i = 0;
  for (; i + 4 <= words; i += 4) {
    s0 += p[i];
    s1 += p[i + 1];
    s2 += p[i + 2];
    s3 += p[i + 3];
  }
  for (; i < words; ++i) s0 += p[i];
  return s0 + s1 + s2 + s3;
}

// What both benchmarks read, in bytes: indices and positions (facesLight), edges (possibleSilhouetteEdges).
std::int64_t bytesRead(const PreparedCaster& c) {
  return static_cast<std::int64_t>(c.mesh.indices.size() * sizeof(std::uint32_t) +
                                   c.mesh.positions.size() * sizeof(glm::vec3) +
                                   c.adjacency.edges.size() * sizeof(Edge));
}

// What the prepared version streams, in bytes: six floats per face, two faces per edge.
std::int64_t preparedBytesRead(const SilhouetteCaster& c) {
  return static_cast<std::int64_t>(6 * c.faceCount() * sizeof(float) +
                                   c.edgeFaces.size() * sizeof(SilhouetteCaster::EdgeFaces));
}

const glm::vec4 light(3.0f, 4.0f, 5.0f, 1.0f);

// The light's distance, for the dual-space table: the shapes have radius 1 (the torus 1.3) about
// the origin. Near: 2.1 away, where the facing flags change fast across the surface; far: 71
// away; directional: towards (3, 4, 5) from infinitely far.
struct LightCase {
  const char* name;
  glm::vec4 position;
};
constexpr LightCase lightCases[] = {{"near", {0.9f, 1.2f, 1.5f, 1.0f}},
                                    {"far", {30.0f, 40.0f, 50.0f, 1.0f}},
                                    {"directional", {3.0f, 4.0f, 5.0f, 0.0f}}};

// The near light moved by a small step: turned 0.1 degrees about the y axis per call, so every
// call queries again for a light a little off the last one (no result can be reused: the light
// moved relative to the caster). 3600 steps make the whole turn.
glm::vec4 steppedLight(std::size_t step) {
  const float a = glm::radians(0.1f) * static_cast<float>(step % 3600);
  const glm::vec4 p = lightCases[0].position;
  return {p.x * std::cos(a) + p.z * std::sin(a), p.y, -p.x * std::sin(a) + p.z * std::cos(a), 1.0f};
}

void meshVersion(benchmark::State& state, const std::string& shape, const Size& size) {
  const PreparedCaster& c = caster(shape, size);
  std::size_t edges = 0;
  for (auto _ : state) {
    const std::vector<bool> lit = facesLight(c.mesh, light);
    const std::vector<SilhouetteEdge> silhouette = possibleSilhouetteEdges(c.adjacency, lit);
    edges = silhouette.size();
    benchmark::DoNotOptimize(silhouette.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.mesh.triangleCount()));
  state.SetBytesProcessed(state.iterations() * bytesRead(c));
  state.counters["triangles"] = static_cast<double>(c.mesh.triangleCount());
  state.counters["silhouette_edges"] = static_cast<double>(edges);
}

void prepared(benchmark::State& state, const std::string& shape, const Size& size) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  std::vector<std::uint8_t> lit;
  std::vector<SilhouetteEdge> silhouette;
  for (auto _ : state) {
    facesLight(c, light, lit);
    possibleSilhouetteEdges(c, lit, silhouette);
    benchmark::DoNotOptimize(silhouette.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.faceCount()));
  state.SetBytesProcessed(state.iterations() * preparedBytesRead(c));
  state.counters["triangles"] = static_cast<double>(c.faceCount());
  state.counters["silhouette_edges"] = static_cast<double>(silhouette.size());
}

void facing(benchmark::State& state, const std::string& shape, const Size& size) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  std::vector<std::uint8_t> lit;
  for (auto _ : state) {
    facesLight(c, light, lit);
    benchmark::DoNotOptimize(lit.data());
  }
  state.counters["triangles"] = static_cast<double>(c.faceCount());
}

void edgepass(benchmark::State& state, const std::string& shape, const Size& size) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  std::vector<std::uint8_t> lit;
  std::vector<SilhouetteEdge> silhouette;
  facesLight(c, light, lit);
  for (auto _ : state) {
    possibleSilhouetteEdges(c, lit, silhouette);
    benchmark::DoNotOptimize(silhouette.data());
  }
  state.counters["triangles"] = static_cast<double>(c.faceCount());
}

void prepare(benchmark::State& state, const std::string& shape, const Size& size) {
  const PreparedCaster& c = caster(shape, size);
  for (auto _ : state) {
    SilhouetteCaster s = prepareSilhouettes(c.mesh, c.adjacency);
    benchmark::DoNotOptimize(s.nx.data());
  }
  state.counters["triangles"] = static_cast<double>(c.mesh.triangleCount());
}

// Wallner's dual space: the hextree's query for the same light (the tree built once, outside).
void dual(benchmark::State& state, const std::string& shape, const Size& size) {
  const DualSilhouettes& tree = dualTree(shape, size);
  std::vector<SilhouetteEdge> silhouette;
  for (auto _ : state) {
    tree.query(light, silhouette);
    benchmark::DoNotOptimize(silhouette.data());
  }
  state.counters["triangles"] = static_cast<double>(silhouetteCaster(shape, size).faceCount());
  state.counters["silhouette_edges"] = static_cast<double>(silhouette.size());
  state.counters["cells_visited"] = static_cast<double>(tree.lastQuery().cellsVisited);
  state.counters["edges_tested"] = static_cast<double>(tree.lastQuery().edgesTested);
}

// The brute force of part 1 (a SilhouetteCaster's two passes) and the dual-space query for one
// light of lightCases, or (index 3) the stepped light.
template <bool Dual>
void byLight(benchmark::State& state, const std::string& shape, const Size& size, std::size_t which) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  const DualSilhouettes* tree = Dual ? &dualTree(shape, size) : nullptr;
  std::vector<std::uint8_t> lit;
  std::vector<SilhouetteEdge> silhouette;
  std::size_t step = 0, edges = 0, calls = 0, tested = 0;
  for (auto _ : state) {
    const glm::vec4 l = which < std::size(lightCases) ? lightCases[which].position : steppedLight(step++);
    if constexpr (Dual) {
      tree->query(l, silhouette);
    } else {
      facesLight(c, l, lit);
      possibleSilhouetteEdges(c, lit, silhouette);
    }
    benchmark::DoNotOptimize(silhouette.data());
    edges += silhouette.size();
    if constexpr (Dual) tested += tree->lastQuery().edgesTested;
    ++calls;
  }
  state.counters["triangles"] = static_cast<double>(c.faceCount());
  state.counters["silhouette_edges"] = calls ? static_cast<double>(edges) / static_cast<double>(calls) : 0.0;
  if constexpr (Dual)
    state.counters["edges_tested"] = calls ? static_cast<double>(tested) / static_cast<double>(calls) : 0.0;
}

void dualPrepare(benchmark::State& state, const std::string& shape, const Size& size) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  for (auto _ : state) {
    DualSilhouettes tree(c);
    benchmark::DoNotOptimize(&tree);
  }
  state.counters["triangles"] = static_cast<double>(c.faceCount());
}

void scanPrepared(benchmark::State& state, const std::string& shape, const Size& size) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  for (auto _ : state) {
    std::uint32_t sum = sumWords(c.nx) + sumWords(c.ny) + sumWords(c.nz) + sumWords(c.ax) + sumWords(c.ay) +
                        sumWords(c.az) + sumWords(c.edgeFaces);
    benchmark::DoNotOptimize(sum);
  }
  state.SetBytesProcessed(state.iterations() * preparedBytesRead(c));
  state.counters["triangles"] = static_cast<double>(c.faceCount());
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
    const std::vector<SilhouetteEdge> silhouette = possibleSilhouetteEdges(c.adjacency, lit);
    benchmark::DoNotOptimize(silhouette.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.mesh.triangleCount()));
  state.counters["triangles"] = static_cast<double>(c.mesh.triangleCount());
}

void scan(benchmark::State& state, const std::string& shape, const Size& size) {
  const PreparedCaster& c = caster(shape, size);
  for (auto _ : state) {
    std::uint32_t sum = sumWords(c.mesh.indices) + sumWords(c.mesh.positions) + sumWords(c.adjacency.edges);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.mesh.triangleCount()));
  state.SetBytesProcessed(state.iterations() * bytesRead(c));
  state.counters["triangles"] = static_cast<double>(c.mesh.triangleCount());
}

// A silhouette of a closed mesh is made of closed loops: every vertex starts as many of its
// directed edges as it ends.
bool closedLoops(const PreparedCaster& c) {
  const std::vector<SilhouetteEdge> edges = possibleSilhouetteEdges(c.adjacency, facesLight(c.mesh, light));
  std::vector<int> balance(c.mesh.positions.size(), 0);
  for (const SilhouetteEdge& e : edges) {
    ++balance[e.v0];
    --balance[e.v1];
  }
  for (int b : balance)
    if (b != 0) return false;
  return !edges.empty();
}

// The prepared version gives the mesh version's edges, in the same order and direction.
bool sameAsMeshVersion(const std::string& shape, const Size& size) {
  const PreparedCaster& c = caster(shape, size);
  const std::vector<SilhouetteEdge> a = possibleSilhouetteEdges(c.adjacency, facesLight(c.mesh, light)),
                                    b = possibleSilhouetteEdges(silhouetteCaster(shape, size), light);
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].v0 != b[i].v0 || a[i].v1 != b[i].v1) return false;
  return true;
}

// The dual-space query gives the prepared passes' edges for every light of the table, and for the
// first steps of the stepped light.
bool dualAsPrepared(const std::string& shape, const Size& size) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  std::vector<SilhouetteEdge> found;
  auto same = [&](const glm::vec4& l) {
    dualTree(shape, size).query(l, found);
    const std::vector<SilhouetteEdge> expected = possibleSilhouetteEdges(c, l);
    if (found.size() != expected.size() || expected.empty()) return false;
    for (std::size_t i = 0; i < found.size(); ++i)
      if (found[i].v0 != expected[i].v0 || found[i].v1 != expected[i].v1) return false;
    return true;
  };
  for (const LightCase& l : lightCases)
    if (!same(l.position)) return false;
  for (std::size_t step = 0; step < 10; ++step)
    if (!same(steppedLight(step))) return false;
  return true;
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

// Keeps each run's time per iteration for the table: the median of its repetitions, which with
// --benchmark_enable_random_interleaving ran interleaved with the other benchmarks', so that a
// busy moment on a shared machine falls on all of them alike.
class TableReporter : public benchmark::ConsoleReporter {
 public:
  struct Row {
    double triangles = 0, edges = 0, tested = 0;
    std::vector<double> ns;  // one per repetition
    double median() const {
      std::vector<double> sorted = ns;
      std::sort(sorted.begin(), sorted.end());
      const std::size_t n = sorted.size();
      return n == 0 ? 0.0 : n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    }
  };
  std::map<std::string, Row> rows;  // by name: "prepared/sphere/1k"

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (failed(run) || run.run_type != Run::RT_Iteration) continue;
      Row& row = rows[run.run_name.function_name];
      row.ns.push_back(run.GetAdjustedCPUTime());  // nanoseconds; CPU time, as the machine may be shared
      row.triangles = run.counters.at("triangles").value;
      if (run.counters.count("silhouette_edges")) row.edges = run.counters.at("silhouette_edges").value;
      if (run.counters.count("edges_tested")) row.tested = run.counters.at("edges_tested").value;
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

double perTriangle(const TableReporter& reporter, const std::string& name) {
  const auto row = reporter.rows.find(name);
  return row == reporter.rows.end() ? 0.0 : row->second.median() / row->second.triangles;
}

void writeDualTable(const TableReporter& reporter, std::ofstream& out);

void writeTable(const TableReporter& reporter, const std::string& file) {
  std::ofstream out(file);
  out << "# Silhouette extraction against a memory scan\n\n"
      << "The possible silhouette edges of welded spheres and tori for a point light at (3, 4, 5), two\n"
      << "ways (common/geometry/shadow_volume.h): **mesh**, `facesLight` + `possibleSilhouetteEdges` on the "
         "mesh "
         "and\n"
      << "its adjacency (a gathered cross product per triangle, bit flags); **prepared**, the same two\n"
      << "passes on a `SilhouetteCaster` (face normals and first corners precomputed once and streamed,\n"
      << "each edge's two faces read once against one-byte flags; identical edges). Each against a scan\n"
      << "that sums the arrays it reads as 32-bit words: **scan** the indices, positions and edges (mesh),\n"
      << "**scan-prepared** the six per-face floats and the edges' face pairs (prepared). Single thread,\n"
      << "CPU time per call, the median of 3 repetitions interleaved at random, all in one benchmark run;\n"
      << "GB/s counts those arrays' bytes once per call.\n"
      << "The halves: facesLight / the facing pass, possibleSilhouetteEdges / the edge pass. prepare: "
         "building\n"
      << "the SilhouetteCaster, once per caster. Written by `cmake --build build --target\n"
      << "silhouette-benchmark` (every repetition's time in silhouette-extraction.csv).\n\n"
      << "| shape | triangles | silhouette edges | mesh ns/tri | (facesLight + possibleSilhouetteEdges) | "
         "scan "
         "ns/tri | "
         "mesh / scan | prepared ns/tri | (facing + edge pass) | prepared GB/s | scan-prepared ns/tri | "
         "scan-prepared GB/s | **prepared / scan-prepared** | prepared / scan | prepare ns/tri (once) |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const char* shape : {"sphere", "torus"})
    for (const Size& size : sizes) {
      const std::string key = std::string("/") + shape + "/" + size.name;
      const auto p = reporter.rows.find("prepared" + key);
      if (p == reporter.rows.end() || reporter.rows.find("scan-prepared" + key) == reporter.rows.end() ||
          reporter.rows.find("mesh" + key) == reporter.rows.end())
        continue;
      const double mesh = perTriangle(reporter, "mesh" + key), scan = perTriangle(reporter, "scan" + key),
                   prep = perTriangle(reporter, "prepared" + key),
                   scanPrep = perTriangle(reporter, "scan-prepared" + key);
      const double bytes = static_cast<double>(preparedBytesRead(silhouetteCaster(shape, size)));
      char line[512];
      std::snprintf(
          line, sizeof line,
          "| %s | %.0f | %.0f | %.2f | %.2f + %.2f | %.2f | %.1f | %.2f | %.2f + %.2f | %.1f | %.2f | %.1f | "
          "**%.2f** | %.2f | %.1f |\n",
          shape, p->second.triangles, p->second.edges, mesh, perTriangle(reporter, "faces" + key),
          perTriangle(reporter, "edges" + key), scan, mesh / scan, prep,
          perTriangle(reporter, "facing" + key), perTriangle(reporter, "edgepass" + key),
          bytes / (prep * p->second.triangles), scanPrep, bytes / (scanPrep * p->second.triangles),
          prep / scanPrep, prep / scan, perTriangle(reporter, "prepare" + key));
      out << line;
    }
  writeDualTable(reporter, out);
}

// The second table: the dual-space query beside part 1's brute force by the light's distance.
void writeDualTable(const TableReporter& reporter, std::ofstream& out) {
  out << "\n## Dual space against the brute force, by the light's distance\n\n"
      << "The possible silhouette edges two ways, identical edges (checked by `--quick`): **brute force**,\n"
      << "the two passes of part 1 on a `SilhouetteCaster` (every face's facing test, every edge's two\n"
      << "flags); **dual**, `DualSilhouettes::query` (common/geometry/dual_silhouette.h), the 4D tree of\n"
      << "face planes descended only where the light's plane crosses a cell, each edge reached tested\n"
      << "exactly. Lights: near (0.9, 1.2, 1.5), 2.1 from the centre of shapes of radius 1 (torus 1.3);\n"
      << "far (30, 40, 50), 71 away; directional towards (3, 4, 5); step, the near light turned 0.1\n"
      << "degrees about y before every call (it moved relative to the caster, so every call queries\n"
      << "again: the re-query cost). Per call, median of the repetitions; the tree's build (dual\n"
      << "prepare) is paid once per caster, apart. Edges tested: those the query decided exactly,\n"
      << "per call (the brute force tests every edge).\n\n"
      << "| shape | triangles | light | silhouette edges | brute force ns/tri | dual ns/tri | **dual / brute "
         "force** | dual edges tested | dual prepare ns/tri (once) |\n"
      << "|---|---:|---|---:|---:|---:|---:|---:|---:|\n";
  for (const char* shape : {"sphere", "torus"})
    for (const Size& size : sizes) {
      const std::string key = std::string("/") + shape + "/" + size.name;
      for (const char* where : {"near", "far", "directional", "step"}) {
        const auto b = reporter.rows.find(std::string("prepared-") + where + key),
                   d = reporter.rows.find(std::string("dual-") + where + key);
        if (b == reporter.rows.end() || d == reporter.rows.end()) continue;
        const double brute = perTriangle(reporter, b->first), dual = perTriangle(reporter, d->first);
        char line[512];
        std::snprintf(line, sizeof line, "| %s | %.0f | %s | %.0f | %.2f | %.2f | **%.2f** | %.0f | %.1f |\n",
                      shape, b->second.triangles, where, d->second.edges, brute, dual, dual / brute,
                      d->second.tested, perTriangle(reporter, "dual-prepare" + key));
        out << line;
      }
    }
}

void writeRaw(const TableReporter& reporter, const std::string& file) {
  std::ofstream out(file);
  out << "benchmark,triangles,silhouette_edges,median_cpu_ns,repetition_cpu_ns\n";
  for (const auto& [name, row] : reporter.rows) {
    out << name << "," << row.triangles << "," << row.edges << "," << row.median() << ",";
    for (std::size_t i = 0; i < row.ns.size(); ++i) out << (i ? " " : "") << row.ns[i];
    out << "\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::string table, raw;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--quick")
      quick = true;
    else if (arg == "--table" && i + 1 < argc)
      table = argv[++i];
    else if (arg == "--raw" && i + 1 < argc)
      raw = argv[++i];
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
      const std::pair<const char*, void (*)(benchmark::State&, const std::string&, const Size&)> runs[] = {
          {"mesh", meshVersion},
          {"prepared", prepared},
          {"scan", scan},
          {"scan-prepared", scanPrepared},
          {"faces", faces},
          {"edges", edges},
          {"facing", facing},
          {"edgepass", edgepass},
          {"prepare", prepare},
          {"dual", dual},
          {"dual-prepare", dualPrepare}};
      for (const auto& [name, run] : runs)
        benchmark::RegisterBenchmark((name + key).c_str(), run, std::string(shape), size);
      for (std::size_t k = 0; k <= std::size(lightCases); ++k) {
        const std::string where = k < std::size(lightCases) ? lightCases[k].name : "step";
        const std::string s = shape;
        benchmark::RegisterBenchmark(("prepared-" + where + key).c_str(),
                                     [s, &size, k](benchmark::State& st) { byLight<false>(st, s, size, k); });
        benchmark::RegisterBenchmark(("dual-" + where + key).c_str(),
                                     [s, &size, k](benchmark::State& st) { byLight<true>(st, s, size, k); });
      }
      if (quick && !dualAsPrepared(shape, size)) {
        std::cerr << shape << " " << size.name
                  << ": the dual-space silhouette differs from the prepared one\n";
        return 1;
      }
      if (quick && !closedLoops(caster(shape, size))) {
        std::cerr << shape << " " << size.name << ": the silhouette is not a set of closed loops\n";
        return 1;
      }
      if (quick && !sameAsMeshVersion(shape, size)) {
        std::cerr << shape << " " << size.name
                  << ": the prepared silhouette differs from the mesh version's\n";
        return 1;
      }
    }
  TableReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  if (!table.empty()) writeTable(reporter, table);
  if (!raw.empty()) writeRaw(reporter, raw);
  benchmark::Shutdown();
  return 0;
}
