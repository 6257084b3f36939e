// The timeline's files: CSV with its sidecar, JSON, numpy's .npy and .npz
// (timeline_csv.hpp). The .npy header follows numpy's format spec (version
// 1.0: magic, version, a little-endian header length, a Python dict literal
// padded to 64 bytes); .npz is a ZIP of .npy files, stored, one per column.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <bit>
#include <cmath>
#include <cstring>
#include <optional>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/checksum.hpp"
#include "core/text.hpp"
#include "jobs/timeline_csv.hpp"

namespace rollspin::jobs {

static_assert(std::endian::native == std::endian::little, "the .npy writer copies little-endian numbers");

namespace {

std::string jsonText(const std::string& text) { return nlohmann::json(text).dump(); }
// JSON has no inf or NaN: null.
std::string jsonNumber(double v) { return std::isfinite(v) ? fmt::format("{:.17g}", v) : "null"; }

std::vector<std::string_view> columnsOf(const RollingModel& model) {
  std::vector<std::string_view> names(kTimelineColumns.begin(), kTimelineColumns.end());
  if (timelineHasSegments(model)) names.emplace_back("segment");
  if (timelineHasSurfaces(model)) names.emplace_back("surface");
  return names;
}

// The sidecar's (and a JSON timeline's) fields, without the braces.
std::string describeSolve(const std::filesystem::path& out, const RollingModel& model, const SolverChoice& choice,
                          const spin::SampleArcLengths& sampleS, const spin::SolveStats& solved,
                          const TimelineFileOptions& o) {
  std::vector<std::string> columns;
  for (const std::string_view c : columnsOf(model)) columns.push_back(jsonText(std::string(c)));
  return fmt::format(
      "  \"rollspin\": {},\n  \"file\": {},\n  \"columns\": [{}],\n  \"samples\": {},\n  \"method\": {},\n"
      "  \"steps\": {},\n  \"error_estimate\": {},\n  \"error_estimate_basis\": {},\n"
      "  \"error_estimate_seconds\": {},\n  \"solve_seconds\": {},\n  \"scene\": {}",
      jsonText("rollspin " ROLLSPIN_VERSION), jsonText(out.filename().string()), fmt::join(columns, ", "),
      sampleS.size(), jsonText(std::string(spin::methodName(choice.method))), solved.steps,
      jsonNumber(solved.errorEstimate), jsonText(solved.errorEstimateBasis), jsonNumber(solved.errorEstimateSeconds),
      jsonNumber(solved.seconds), jsonText(o.sceneText));
}

// Today's comment line, for --comment-header.
std::string commentLine(const SolverChoice& choice, const spin::SolveStats& solved) {
  // A skipped estimate (solver.error_estimate = false) is NaN: say so, not "nan rad".
  if (std::isnan(solved.errorEstimate))
    return fmt::format("# rollspin timeline: {} with {} steps; error estimate of U(L) {} (the solve {:.3g} s)\n",
                       spin::methodName(choice.method), solved.steps, solved.errorEstimateBasis, solved.seconds);
  return fmt::format(
      "# rollspin timeline: {} with {} steps; error estimate of U(L) {:.2g} rad ({}; took {:.3g} s, "
      "the solve {:.3g} s)\n",
      spin::methodName(choice.method), solved.steps, solved.errorEstimate, solved.errorEstimateBasis,
      solved.errorEstimateSeconds, solved.seconds);
}

// Rows go through `buffer`, handed to the file in ~1 MiB chunks.
class ChunkedWriter {
 public:
  explicit ChunkedWriter(AtomicFile& file) : file_(file) {}
  fmt::memory_buffer& buffer() { return buffer_; }
  void maybeFlush() {
    if (buffer_.size() > (1u << 20)) flush();
  }
  void flush() {
    file_.write({buffer_.data(), buffer_.size()});
    buffer_.clear();
  }

 private:
  AtomicFile& file_;
  fmt::memory_buffer buffer_;
};

// numpy's .npy header (format 1.0) for `descr` and `shape`.
std::string npyHeader(const std::string& descr, const std::string& shape) {
  std::string dict = fmt::format("{{'descr': {}, 'fortran_order': False, 'shape': {}, }}", descr, shape);
  const std::size_t total = 10 + dict.size() + 1;  // magic 6, version 2, length 2, the dict, '\n'
  dict.append((64 - total % 64) % 64, ' ');
  dict += '\n';
  std::string out("\x93NUMPY\x01\x00", 8);
  out += static_cast<char>(dict.size() & 0xFF);
  out += static_cast<char>(dict.size() >> 8);
  return out + dict;
}

template <typename T>
void appendRaw(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

void appendLittle(std::string& out, std::uint32_t v, int bytes) {
  for (int k = 0; k < bytes; ++k) out += static_cast<char>((v >> (8 * k)) & 0xFFU);
}

// A ZIP of stored (uncompressed) members: local headers, the data, the
// central directory, its end record (APPNOTE 4.3; no ZIP64: under 4 GiB).
std::string storedZip(const std::vector<std::pair<std::string, std::string>>& members, const std::string& name) {
  std::string out, central;
  constexpr std::uint32_t kDate = (0U << 9) | (1U << 5) | 1U;  // 1980-01-01: a fixed time, reproducible
  for (const auto& [member, data] : members) {
    if (out.size() + data.size() > 0xFFFFFFF0ULL)
      throw runtimeError(SourceLoc{name}, "the .npz would pass 4 GiB (no ZIP64 here): write .npy or .csv");
    const std::uint32_t crc = crc32(data), offset = static_cast<std::uint32_t>(out.size());
    const auto size = static_cast<std::uint32_t>(data.size());
    const auto nameSize = static_cast<std::uint32_t>(member.size());
    const auto common = [&](std::string& h) {
      appendLittle(h, 20, 2), appendLittle(h, 0, 2), appendLittle(h, 0, 2), appendLittle(h, 0, 2);
      appendLittle(h, kDate, 2), appendLittle(h, crc, 4), appendLittle(h, size, 4), appendLittle(h, size, 4);
      appendLittle(h, nameSize, 2), appendLittle(h, 0, 2);
    };
    appendLittle(out, 0x04034b50U, 4);
    common(out);
    out += member + data;
    appendLittle(central, 0x02014b50U, 4);
    appendLittle(central, 20, 2);  // made by
    common(central);
    appendLittle(central, 0, 2), appendLittle(central, 0, 2), appendLittle(central, 0, 2);  // comment, disk, internal
    appendLittle(central, 0, 4), appendLittle(central, offset, 4);
    central += member;
  }
  const auto count = static_cast<std::uint32_t>(members.size());
  const auto centralAt = static_cast<std::uint32_t>(out.size());
  out += central;
  appendLittle(out, 0x06054b50U, 4), appendLittle(out, 0, 2), appendLittle(out, 0, 2);
  appendLittle(out, count, 2), appendLittle(out, count, 2);
  appendLittle(out, static_cast<std::uint32_t>(central.size()), 4), appendLittle(out, centralAt, 4);
  appendLittle(out, 0, 2);
  return out;
}

// A device or a pipe (-o /dev/stdout): CSV, without a sidecar.
bool isStream(const std::filesystem::path& out) {
  std::error_code ec;
  const auto status = std::filesystem::status(out, ec);
  return !ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
         !std::filesystem::is_directory(status);
}

}  // namespace

TimelineFormat timelineFormatOf(const std::filesystem::path& out, const SourceLoc& where) {
  if (isStream(out)) return TimelineFormat::Csv;
  const std::string extension = asciiLowercase(out.extension().string());
  if (extension == ".csv") return TimelineFormat::Csv;
  if (extension == ".json") return TimelineFormat::Json;
  if (extension == ".npy") return TimelineFormat::Npy;
  if (extension == ".npz") return TimelineFormat::Npz;
  throw badInput(where, "expected a timeline file NAME.csv, NAME.json, NAME.npy or NAME.npz, got '{}'",
                 extension.empty() ? out.filename().string() : extension);
}

namespace {

spin::SolveStats writeText(AtomicFile& file, TimelineFormat format, const std::filesystem::path& out,
                           const RollingModel& model, const SolverChoice& choice, const spin::SampleArcLengths& sampleS,
                           const spin::SolveStats& solved, const TimelineFileOptions& o) {
  ChunkedWriter writer(file);
  auto& buffer = writer.buffer();
  const bool json = format == TimelineFormat::Json, segments = timelineHasSegments(model);
  const bool surfaces = timelineHasSurfaces(model);
  if (json) {
    fmt::format_to(std::back_inserter(buffer), "{{\n{},\n  \"rows\": [",
                   describeSolve(out, model, choice, sampleS, solved, o));
  } else {
    if (o.commentHeader) fmt::format_to(std::back_inserter(buffer), "{}", commentLine(choice, solved));
    fmt::format_to(std::back_inserter(buffer), "{}\n", fmt::join(columnsOf(model), ","));
  }
  const spin::SolveStats stats = sampleTimeline(
      model, choice, sampleS,
      [&](std::size_t index, const TimelineRow& row) {
        if (json) {
          fmt::format_to(std::back_inserter(buffer), "{}\n    [", index == 0 ? "" : ",");
          for (std::size_t k = 0; k < row.values.size(); ++k)
            fmt::format_to(std::back_inserter(buffer), "{}{}", k == 0 ? "" : ", ", jsonNumber(row.values[k]));
          if (segments) fmt::format_to(std::back_inserter(buffer), ", {}", row.segment);
          if (surfaces) fmt::format_to(std::back_inserter(buffer), ", {}", row.surface);
          buffer.push_back(']');
        } else {
          fmt::format_to(std::back_inserter(buffer), "{:.17g}", fmt::join(row.values, ","));
          if (segments) fmt::format_to(std::back_inserter(buffer), ",{}", row.segment);
          if (surfaces) fmt::format_to(std::back_inserter(buffer), ",{}", row.surface);
          buffer.push_back('\n');
        }
        writer.maybeFlush();
      },
      out.string());
  if (json) fmt::format_to(std::back_inserter(buffer), "\n  ]\n}}\n");
  writer.flush();
  return stats;
}

// .npy: one structured array of N records (every column a field, '<f8';
// the storyboard's segment and surface '<i8'), streamed. .npz: a 1-D array per column.
spin::SolveStats writeNumpy(AtomicFile& file, TimelineFormat format, const std::filesystem::path& out,
                            const RollingModel& model, const SolverChoice& choice,
                            const spin::SampleArcLengths& sampleS) {
  const std::vector<std::string_view> names = columnsOf(model);
  const bool segments = timelineHasSegments(model), surfaces = timelineHasSurfaces(model);
  const auto typeOf = [](std::string_view column) {
    return column == "segment" || column == "surface" ? "<i8" : "<f8";
  };
  if (format == TimelineFormat::Npy) {
    std::vector<std::string> fields;
    for (const std::string_view c : names) fields.push_back(fmt::format("('{}', '{}')", c, typeOf(c)));
    ChunkedWriter writer(file);
    const std::string header =
        npyHeader(fmt::format("[{}]", fmt::join(fields, ", ")), fmt::format("({},)", sampleS.size()));
    writer.buffer().append(header.data(), header.data() + header.size());
    std::string record;
    const spin::SolveStats stats = sampleTimeline(
        model, choice, sampleS,
        [&](std::size_t, const TimelineRow& row) {
          record.clear();
          for (const double v : row.values) appendRaw(record, v);
          if (segments) appendRaw(record, static_cast<std::int64_t>(row.segment));
          if (surfaces) appendRaw(record, static_cast<std::int64_t>(row.surface));
          writer.buffer().append(record.data(), record.data() + record.size());
          writer.maybeFlush();
        },
        out.string());
    writer.flush();
    return stats;
  }
  std::vector<std::string> columns(names.size());
  const spin::SolveStats stats = sampleTimeline(
      model, choice, sampleS,
      [&](std::size_t, const TimelineRow& row) {
        for (std::size_t k = 0; k < row.values.size(); ++k) appendRaw(columns[k], row.values[k]);
        const std::size_t extra = row.values.size();
        if (segments) appendRaw(columns[extra], static_cast<std::int64_t>(row.segment));
        if (surfaces) appendRaw(columns[extra + (segments ? 1 : 0)], static_cast<std::int64_t>(row.surface));
      },
      out.string());
  std::vector<std::pair<std::string, std::string>> members;
  for (std::size_t k = 0; k < names.size(); ++k)
    members.emplace_back(
        fmt::format("{}.npy", names[k]),
        npyHeader(fmt::format("'{}'", typeOf(names[k])), fmt::format("({},)", sampleS.size())) + columns[k]);
  file.write(storedZip(members, out.string()));
  return stats;
}

}  // namespace

spin::SolveStats writeTimelineFile(const std::filesystem::path& out, const RollingModel& model,
                                   const SolverChoice& choice, const spin::SampleArcLengths& sampleS,
                                   const spin::SolveStats& solved, const TimelineFileOptions& options) {
  const TimelineFormat format = timelineFormatOf(out, SourceLoc{"-o " + out.string()});
  AtomicFile file(out);
  const bool text = format == TimelineFormat::Csv || format == TimelineFormat::Json;
  const spin::SolveStats stats = text ? writeText(file, format, out, model, choice, sampleS, solved, options)
                                      : writeNumpy(file, format, out, model, choice, sampleS);
  // The sidecar: the solve's numbers, the scene and the version beside the data.
  std::optional<AtomicFile> sidecar;
  if (format != TimelineFormat::Json && !isStream(out)) {
    std::filesystem::path sidecarPath = out;
    sidecarPath += ".json";
    sidecar.emplace(sidecarPath);
    sidecar->write(fmt::format("{{\n{}\n}}\n", describeSolve(out, model, choice, sampleS, solved, options)));
  }
  file.commit();
  if (sidecar) sidecar->commit();
  return stats;
}

}  // namespace rollspin::jobs
