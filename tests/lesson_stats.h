// A lesson's --stats JSON (README, "Every lesson takes the same flags"), read back for tests and
// sweeps with nlohmann-json: the lesson's own counts, per-pass figures summed over every pass of
// a name (a pass repeated per light adds up), the totals and the frame times.
#pragma once
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace stencil::testing {

class LessonStats {
 public:
  LessonStats() = default;
  // Throws nlohmann::json::parse_error on text that is not JSON.
  explicit LessonStats(const std::string& text) : json_(nlohmann::json::parse(text)) {}

  static LessonStats read(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error("cannot read " + file.string());
    return LessonStats(std::string(std::istreambuf_iterator<char>(in), {}));
  }

  bool empty() const { return json_.is_null(); }
  const nlohmann::json& json() const { return json_; }

  // A count the lesson reported (Frame::count, under "counts"); -1 when it reported none.
  long long count(const std::string& name) const {
    const auto& counts = json_.at("counts");
    return counts.contains(name) ? counts.at(name).get<long long>() : -1;
  }

  // A per-pass field ("triangles", "samples_passed", "draw_calls", ...) summed over every pass
  // named `pass`. Throws std::runtime_error when no pass has that name, or the field is null
  // in one (a query the driver lacks).
  double passSum(const std::string& pass, const std::string& field) const {
    double total = 0;
    int found = 0;
    for (const auto& p : json_.at("passes")) {
      if (p.at("name") != pass) continue;
      if (p.at(field).is_null()) throw std::runtime_error("pass " + pass + " has no " + field);
      total += p.at(field).get<double>();
      ++found;
    }
    if (found == 0) throw std::runtime_error("no pass named " + pass + " in the stats");
    return total;
  }
  long long passTotal(const std::string& pass, const std::string& field) const {
    return static_cast<long long>(passSum(pass, field));
  }

  // How many passes ran under this name (a pass repeated per light or product counts each time).
  long long passCount(const std::string& pass) const {
    long long n = 0;
    for (const auto& p : json_.at("passes")) n += p.at("name") == pass;
    return n;
  }

  // The first pass named `pass`: one of its fields.
  long long firstPass(const std::string& pass, const std::string& field) const {
    for (const auto& p : json_.at("passes"))
      if (p.at("name") == pass) return p.at(field).get<long long>();
    throw std::runtime_error("no pass named " + pass + " in the stats");
  }

  // A field of "total" (every pass): "triangles", "draw_calls", ...
  long long total(const std::string& field) const { return json_.at("total").at(field).get<long long>(); }

  // A frame time in milliseconds: "first", "mean", "min" or "max".
  double frameMs(const std::string& which) const { return json_.at("frame_ms").at(which).get<double>(); }

  bool feature(const std::string& name) const { return json_.at("features").at(name).get<bool>(); }

 private:
  nlohmann::json json_;
};

}  // namespace stencil::testing
