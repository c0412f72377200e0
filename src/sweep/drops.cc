#include "src/sweep/drops.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <random>
#include <sstream>
#include <stdexcept>

#include "src/numerics/library_threads.h"
#include "src/output/atomic_file.h"
#include "src/output/csv_field.h"
#include "src/output/csv_record.h"
#include "src/output/json.h"
#include "src/output/provenance.h"
#include "src/output/result_folder.h"
#include "src/output/writers.h"
#include "src/parallel/farm_record.h"
#include "src/parallel/process_group.h"
#include "src/parallel/task_farm.h"
#include "src/run/solve_report.h"
#include "src/run/state_text.h"
#include "src/scene/drape_tester.h"
#include "src/solvers/solver.h"
#include "src/sweep/drops_report.h"
#include "src/sweep/sweep.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

constexpr int kWavinessModes = 12;     // angular modes 1 … 12 in the initial waviness
constexpr int kWavinessSamples = 720;  // angles on which max |g| is found

// The two independent draws of a drop.
enum class Stream : std::uint64_t { kPlacement = 1, kWaviness = 2 };

// SplitMix64's finaliser (Steele, Lea & Flood 2014): a well-mixed 64-bit seed from a small one.
std::uint64_t Mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// The generator of one drop's draw: seeded by the scene's seed, the drop and the stream alone.
// Uniform and normal numbers are made here from its raw 64-bit output (the standard library's
// distributions are not the same on every platform).
class DropRandom {
 public:
  DropRandom(int seed, int drop, Stream stream)
      : engine_(Mix(Mix(Mix(static_cast<std::uint64_t>(seed)) ^ static_cast<std::uint64_t>(drop)) ^
                    static_cast<std::uint64_t>(stream))) {}
  double Uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double Normal() {                                                              // Box–Muller
    const double u = 1.0 - Uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * M_PI * Uniform());
  }

 private:
  std::mt19937_64 engine_;
};

Eigen::Vector2d PlacementShift(const DrapeTestSpec& test, int drop) {
  DropRandom random(test.seed, drop, Stream::kPlacement);
  const double r = test.placement * std::sqrt(random.Uniform());
  const double angle = 2.0 * M_PI * random.Uniform();
  return r * Eigen::Vector2d(std::cos(angle), std::sin(angle));
}

// g(θ) = Σ a_m cos mθ + b_m sin mθ, scaled so that max |g| = 1.
struct AngularWave {
  std::vector<double> a, b;
  double scale = 1.0;
  double operator()(double angle) const {
    double g = 0.0;
    for (size_t m = 0; m < a.size(); ++m) {
      g += a[m] * std::cos((m + 1.0) * angle) + b[m] * std::sin((m + 1.0) * angle);
    }
    return g * scale;
  }
};

AngularWave DrawWave(const DrapeTestSpec& test, int drop) {
  DropRandom random(test.seed, drop, Stream::kWaviness);
  AngularWave wave;
  for (int m = 0; m < kWavinessModes; ++m) {
    wave.a.push_back(random.Normal());
    wave.b.push_back(random.Normal());
  }
  double largest = 0.0;
  for (int k = 0; k < kWavinessSamples; ++k) {
    largest = std::max(largest, std::abs(wave(2.0 * M_PI * k / kWavinessSamples)));
  }
  wave.scale = largest > 0.0 ? 1.0 / largest : 0.0;
  return wave;
}

// A farm task's result: a FarmRecord with the drops.csv row and the outline (centre, radii) as
// its numbers.
std::string TaskResult(const DropRecord& record, const DropOutline& outline) {
  std::vector<double> numbers = {outline.centre.x(), outline.centre.y()};
  numbers.insert(numbers.end(), outline.radius.begin(), outline.radius.end());
  const std::string kind = record.state == "interrupted" ? "interrupted" : "solved";
  return EncodeFarmRecords({{kind, record.drop, DropCsvRow(record), numbers}});
}

DropOutline OutlineOf(const FarmRecord& record) {
  DropOutline outline;
  outline.centre = Eigen::Vector2d(record.numbers[0], record.numbers[1]);
  outline.radius.assign(record.numbers.begin() + 2, record.numbers.end());
  return outline;
}

std::string SolveDrop(const Scene& scene, const DropsOptions& options, int drop) {
  DropRecord record;
  record.drop = drop;
  Scene drop_scene = DropScene(scene, drop, &record.offset);
  // Each drop's drape.glb, whatever the scene asks, for the report's 3D view.
  std::vector<std::string>& write = drop_scene.output.write;
  if (std::find(write.begin(), write.end(), "gltf") == write.end()) write.push_back("gltf");
  record.waviness = drop_scene.drape_test->waviness;
  Model model = BuildModel(drop_scene);
  AddDropWaviness(drop_scene, drop, &model);
  const std::string folder =
      (fs::path(options.directory) / DropFolderName(drop, options.drops)).string();
  ResultFolderLock lock(folder);
  const SolveReport report = SolveAndReport(drop_scene, model, drop_scene.solver.method, {},
                                            /*automatic_levels=*/false);
  const RunResult& result = report.result;
  if (InterruptRequested()) {
    record.state = "interrupted";
    return TaskResult(record, {});
  }
  WriteOutputs(drop_scene, model, report, folder,
               Provenance{options.command_line + " (drop " + std::to_string(drop) + ")",
                          options.overrides, options.calibration});
  record.drape_coefficient = report.drape ? report.drape->coefficient.cusick : 0.0;
  record.folds = report.drape ? report.drape->folds.count : 0;
  record.energy = result.certificate.energy;
  record.state = result.converged ? StateText(result) : "not converged: " + StateText(result);
  record.counted =
      result.converged && !result.Saddle() && !result.PassesThrough() && report.drape.has_value();
  DropOutline outline;
  if (report.drape) {
    outline.centre =
        Eigen::Vector2d(report.drape->profile.centre[0], report.drape->profile.centre[1]);
    outline.radius = report.drape->profile.radius;
  }
  return TaskResult(record, outline);
}

// A drop that fails (an input the model refuses, out of memory, a folder that cannot be written)
// is a row saying why, not an abort.
std::string RunDrop(const Scene& scene, const DropsOptions& options, int drop) {
  try {
    return SolveDrop(scene, options, drop);
  } catch (const std::exception& error) {
    DropRecord failed;
    failed.drop = drop;
    DropScene(scene, drop, &failed.offset);
    failed.state = std::string("failed: ") + error.what();
    return TaskResult(failed, {});
  }
}

std::string FoldsText(const std::vector<int>& counts) {
  std::string text;
  for (size_t k = 0; k < counts.size(); ++k) {
    text += (k == 0 ? "" : (k + 1 == counts.size() ? " and " : ", ")) + std::to_string(counts[k]);
  }
  return text;
}

void WriteDropsSummary(const Scene& scene, const DropsOptions& options, const DropsSummary& summary,
                       std::ostream& out) {
  const DropStatistics& s = summary.statistics;
  const DrapeTestSpec& test = *scene.drape_test;
  std::vector<std::pair<std::string, std::string>> histogram;
  for (const auto& [folds, count] : s.folds_histogram) {
    histogram.emplace_back(std::to_string(folds), std::to_string(count));
  }
  std::vector<std::string> modal;
  for (int folds : s.modal_folds) modal.push_back(std::to_string(folds));
  const bool any = s.counted > 0;
  const auto advice = any ? SpecimenSizeAdvice(test.specimen_diameter, s.mean) : std::nullopt;
  std::vector<std::pair<std::string, std::string>> members = {
      {"scene", JsonString(scene.name)},
      {"drops", std::to_string(s.drops)},
      {"drops_counted", std::to_string(s.counted)},
      {"perturbation", JsonInlineObject({{"seed", std::to_string(test.seed)},
                                         {"placement_m", JsonNumber(test.placement)},
                                         {"waviness_m", JsonNumber(test.waviness)}})},
      {"drape_coefficient_mean", any ? JsonNumber(s.mean) : "null"},
      {"drape_coefficient_standard_deviation", any ? JsonNumber(s.standard_deviation) : "null"},
      {"folds_histogram", JsonInlineObject(histogram)},
      {"most_frequent_folds", JsonList(modal)},
      {"most_frequent_folds_drops", std::to_string(s.modal_drops)},
      {"most_frequent_folds_drape_coefficient_mean", any ? JsonNumber(s.modal_mean) : "null"},
      {"specimen_size_advice", advice ? JsonString(*advice) : "null"}};
  if (summary.mesh_advice) members.emplace_back("mesh_rule", MeshRuleJson(*summary.mesh_advice));
  for (auto& member : ProvenanceMembers(
           Provenance{options.command_line, options.overrides, options.calibration})) {
    members.push_back(std::move(member));
  }
  out << JsonObject(members, 0) << "\n";
}

}  // namespace

std::string DropFolderName(int drop, int drops) {
  char name[16];
  std::snprintf(name, sizeof name, "%0*d", drops < 100 ? 2 : (drops < 1000 ? 3 : 4), drop);
  return std::string("drops/") + name;
}

Scene DropScene(const Scene& scene, int drop, Eigen::Vector2d* offset) {
  Scene drop_scene = scene;
  DrapeTestSpec& test = *drop_scene.drape_test;
  test.offset += PlacementShift(test, drop);
  if (offset) *offset = test.offset;
  ExpandDrapeTest(&drop_scene);
  drop_scene.solver.levels = 1;
  return drop_scene;
}

void AddDropWaviness(const Scene& drop_scene, int drop, Model* model) {
  const DrapeTestSpec& test = *drop_scene.drape_test;
  if (test.waviness <= 0.0) return;
  const AngularWave wave = DrawWave(test, drop);
  const double rim = test.disc_diameter / 2;
  const double edge = test.specimen_diameter / 2;
  for (int node = 0; node < model->num_nodes; ++node) {
    if (model->fixed[3 * node + 2]) continue;
    const Eigen::Vector3d p = model->position(node);
    const Eigen::Vector2d from_centre = p.head<2>() - test.offset;
    const double r = from_centre.norm();
    if (r <= rim) continue;
    const double s = std::min(1.0, (r - rim) / (edge - rim));
    model->positions[3 * node + 2] +=
        test.waviness * wave(std::atan2(from_centre.y(), from_centre.x())) * s * s;
  }
}

DropStatistics ComputeDropStatistics(const std::vector<DropRecord>& drops) {
  DropStatistics s;
  s.drops = static_cast<int>(drops.size());
  double sum = 0.0;
  for (const DropRecord& drop : drops) {
    if (!drop.counted) continue;
    ++s.counted;
    sum += drop.drape_coefficient;
    ++s.folds_histogram[drop.folds];
  }
  if (s.counted == 0) return s;
  s.mean = sum / s.counted;
  double squares = 0.0;
  for (const DropRecord& drop : drops) {
    if (drop.counted)
      squares += (drop.drape_coefficient - s.mean) * (drop.drape_coefficient - s.mean);
  }
  s.standard_deviation = s.counted > 1 ? std::sqrt(squares / (s.counted - 1)) : 0.0;
  int most = 0;
  for (const auto& [folds, count] : s.folds_histogram) most = std::max(most, count);
  for (const auto& [folds, count] : s.folds_histogram) {
    if (count == most) s.modal_folds.push_back(folds);
  }
  double modal_sum = 0.0;
  for (const DropRecord& drop : drops) {
    if (!drop.counted ||
        std::find(s.modal_folds.begin(), s.modal_folds.end(), drop.folds) == s.modal_folds.end()) {
      continue;
    }
    ++s.modal_drops;
    modal_sum += drop.drape_coefficient;
  }
  s.modal_mean = modal_sum / s.modal_drops;
  return s;
}

namespace {

// One coordinate of the drop's offset as a column.
CsvColumn<DropRecord> OffsetColumn(std::string name, int axis) {
  return {std::move(name), [axis](const DropRecord& r) { return CsvCellText(r.offset[axis]); },
          [axis](const std::string& cell, DropRecord& r) { ReadCsvCell(cell, &r.offset[axis]); }};
}

const CsvColumns<DropRecord>& DropColumns() {
  static const CsvColumns<DropRecord> columns = {
      MemberColumn("drop", &DropRecord::drop),
      OffsetColumn("offset_x_m", 0),
      OffsetColumn("offset_y_m", 1),
      MemberColumn("waviness_m", &DropRecord::waviness),
      MemberColumn("drape_coefficient", &DropRecord::drape_coefficient),
      MemberColumn("folds", &DropRecord::folds),
      MemberColumn("energy_J", &DropRecord::energy),
      MemberColumn("counted", &DropRecord::counted),
      MemberColumn("state", &DropRecord::state),
  };
  return columns;
}

}  // namespace

std::string DropsCsvHeader() { return CsvHeader(DropColumns()); }

std::string DropCsvRow(const DropRecord& record) { return CsvRow(DropColumns(), record); }

DropRecord ParseDropCsvRow(const std::string& row) {
  std::optional<DropRecord> record = ParseCsvRow(DropColumns(), row);
  if (!record)
    throw std::runtime_error("a drops.csv row that is not " + DropsCsvHeader() + ": " + row);
  return *record;
}

DropsSummary RunDrops(const Scene& scene, const DropsOptions& options, std::ostream& log) {
  RunLibrariesOnOneThread();  // one thread per drop for CHOLMOD and OpenBLAS
  // By the coordinator alone: on every rank, one rank's removal of the folder it made could race
  // another's probe of it (src/sweep/sweep.cc does the same).
  if (Processes().IsCoordinator()) CheckOutputWritable(options.directory);
  fs::create_directories(options.directory);
  std::vector<int> tasks(options.drops);
  for (int k = 0; k < options.drops; ++k) tasks[k] = k;
  std::vector<std::string> rows(options.drops);
  std::vector<DropRecord> records(options.drops);
  std::vector<DropOutline> outlines(options.drops);
  int finished = 0;
  TaskFarmOptions farm_options;
  farm_options.local_threads = options.threads;
  const TaskFarmSummary farm = RunTaskFarm(
      tasks, [&](int task) { return RunDrop(scene, options, task + 1); },
      [&](int task, const std::string& result) {
        const FarmRecord record_of_task = DecodeFarmRecords(result).at(0);
        rows[task] = record_of_task.row;
        outlines[task] = OutlineOf(record_of_task);
        records[task] = ParseDropCsvRow(rows[task]);
        const DropRecord& record = records[task];
        char text[96];
        std::snprintf(text, sizeof text,
                      "drop %d (%d of %d done): drape coefficient %.3f, %d folds, ", record.drop,
                      ++finished, options.drops, record.drape_coefficient, record.folds);
        log << text << record.state << std::endl;
      },
      farm_options);
  DropsSummary summary;
  summary.coordinator = farm.coordinator;
  summary.workers = farm.workers;
  if (!farm.coordinator) return summary;
  summary.drops = records;
  summary.outlines = outlines;
  summary.statistics = ComputeDropStatistics(summary.drops);
  const Scene first = DropScene(scene, 1);
  summary.mesh_advice = AdviseMeshOfScene(first);  // no model built for the rule alone
  const fs::path directory(options.directory);
  WriteAtomically(directory / "drops.csv", [&](std::ostream& out) {
    out << DropsCsvHeader() << '\n';
    for (const std::string& row : rows) out << row << '\n';
  });
  WriteAtomically(directory / "summary.json",
                  [&](std::ostream& out) { WriteDropsSummary(scene, options, summary, out); });
  WriteAtomically(directory / "report.html", [&](std::ostream& out) {
    WriteDropsReport(scene, summary,
                     Provenance{options.command_line, options.overrides, options.calibration}, out,
                     directory);
  });
  return summary;
}

std::string DropsLine(const DropStatistics& s, const std::optional<MeshAdvice>& mesh_advice) {
  std::string text = std::to_string(s.drops) + (s.drops == 1 ? " drop" : " drops");
  if (s.counted < s.drops) {
    text += " (" + std::to_string(s.counted) + " at a stable minimum, counted)";
  }
  if (s.counted == 0) return text + ": none counted, no drape coefficient";
  char figures[160];
  std::snprintf(figures, sizeof figures,
                ": drape coefficient %.3f ± %.3f (mean ± standard deviation)", s.mean,
                s.standard_deviation);
  text += figures;
  if (mesh_advice) {
    text += ", discretisation error about " + RoundedNumber(mesh_advice->expected_error, 2) + " (" +
            MeshRuleBasis(mesh_advice->bending_length) + ")";
  }
  text += "; folds";
  std::string histogram;
  for (const auto& [folds, count] : s.folds_histogram) {
    histogram +=
        (histogram.empty() ? " " : ", ") + std::to_string(folds) + " ×" + std::to_string(count);
  }
  std::snprintf(figures, sizeof figures, "; the most frequent, %s folds (%d of %d): %.3f",
                FoldsText(s.modal_folds).c_str(), s.modal_drops, s.counted, s.modal_mean);
  return text + histogram + figures;
}

}  // namespace drape
