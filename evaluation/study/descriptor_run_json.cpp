#include "evaluation/study/descriptor_run_json.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace radarpr {
namespace {

using nlohmann::json;

json number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

json optional_number(const std::optional<double>& value) {
  return value ? number(*value) : json(nullptr);
}

const json& field(const json& object, const char* key) {
  if (!object.is_object() || !object.contains(key)) {
    throw std::runtime_error(fmt::format("descriptor result: missing field '{}'", key));
  }
  return object.at(key);
}

double read_number(const json& value) {
  if (value.is_number()) return value.get<double>();
  if (value == "nan") return std::numeric_limits<double>::quiet_NaN();
  if (value == "inf") return std::numeric_limits<double>::infinity();
  if (value == "-inf") return -std::numeric_limits<double>::infinity();
  throw std::runtime_error(fmt::format("descriptor result: {} is not a number", value.dump()));
}

std::optional<double> read_optional(const json& value) {
  if (value.is_null()) return std::nullopt;
  return read_number(value);
}

json metrics_to_json(const Metrics& m) {
  json recall_at_k = json::array();
  for (const auto& [k, value] : m.recall_at_k) recall_at_k.push_back({k, optional_number(value)});
  json recall_all_queries = json::array();
  for (const auto& [k, value] : m.recall_at_k_all_queries) {
    recall_all_queries.push_back({k, optional_number(value)});
  }
  json recall_with_positive = json::array();
  for (const auto& [k, value] : m.recall_at_k_with_positive) {
    recall_with_positive.push_back({k, optional_number(value)});
  }
  return {{"queries", m.queries},
          {"revisits", m.revisits},
          {"correct_top1", m.correct_top1},
          {"roc_auc", optional_number(m.roc_auc)},
          {"f1_max", optional_number(m.f1_max)},
          {"f1_max_threshold", optional_number(m.f1_max_threshold)},
          {"pr_auc", optional_number(m.pr_auc)},
          {"average_precision", optional_number(m.average_precision)},
          {"pr_auc_mulran", optional_number(m.pr_auc_mulran)},
          {"recall_at_1", optional_number(m.recall_at_1)},
          {"recall_at_k", recall_at_k},
          {"recall_at_k_all_queries", recall_all_queries},
          {"recall_at_1_all_queries", optional_number(m.recall_at_1_all_queries)},
          {"recall_at_1_with_positive", optional_number(m.recall_at_1_with_positive)},
          {"recall_at_k_with_positive", recall_with_positive},
          {"pr_auc_vpr_bench", optional_number(m.pr_auc_vpr_bench)},
          {"recall_at_100_precision", optional_number(m.recall_at_100_precision)},
          {"extended_precision", optional_number(m.extended_precision)},
          {"extended_precision_vpr_bench", optional_number(m.extended_precision_vpr_bench)}};
}

Metrics metrics_from_json(const json& j) {
  Metrics m;
  m.queries = field(j, "queries").get<std::size_t>();
  m.revisits = field(j, "revisits").get<std::size_t>();
  m.correct_top1 = field(j, "correct_top1").get<std::size_t>();
  m.roc_auc = read_optional(field(j, "roc_auc"));
  m.f1_max = read_optional(field(j, "f1_max"));
  m.f1_max_threshold = read_optional(field(j, "f1_max_threshold"));
  m.pr_auc = read_optional(field(j, "pr_auc"));
  m.average_precision = read_optional(field(j, "average_precision"));
  m.pr_auc_mulran = read_optional(field(j, "pr_auc_mulran"));
  m.recall_at_1 = read_optional(field(j, "recall_at_1"));
  for (const auto& entry : field(j, "recall_at_k")) {
    m.recall_at_k[entry.at(0).get<int>()] = read_optional(entry.at(1));
  }
  for (const auto& entry : field(j, "recall_at_k_all_queries")) {
    m.recall_at_k_all_queries[entry.at(0).get<int>()] = read_optional(entry.at(1));
  }
  m.recall_at_100_precision = read_optional(field(j, "recall_at_100_precision"));
  m.extended_precision = read_optional(field(j, "extended_precision"));
  // Written since the Open-RadVLAD and VPR-Bench presets: a result stored before has none.
  const auto optional_field = [&](const char* key) {
    return j.contains(key) ? read_optional(j.at(key)) : std::nullopt;
  };
  m.recall_at_1_all_queries = optional_field("recall_at_1_all_queries");
  m.recall_at_1_with_positive = optional_field("recall_at_1_with_positive");
  m.pr_auc_vpr_bench = optional_field("pr_auc_vpr_bench");
  m.extended_precision_vpr_bench = optional_field("extended_precision_vpr_bench");
  if (j.contains("recall_at_k_with_positive")) {
    for (const auto& entry : j.at("recall_at_k_with_positive")) {
      m.recall_at_k_with_positive[entry.at(0).get<int>()] = read_optional(entry.at(1));
    }
  }
  return m;
}

}  // namespace

nlohmann::json descriptor_run_to_json(const DescriptorRun& run) {
  json results = json::array();
  for (const auto& r : run.evaluation.results) {
    results.push_back(
        {r.query, r.match, number(r.distance), r.correct, r.revisit, r.first_correct_rank});
  }
  json curve = json::array();
  for (const auto& p : run.evaluation.curve) {
    curve.push_back({number(p.threshold), p.counts.tp, p.counts.fp, p.counts.fn, p.counts.tn,
                     optional_number(p.precision), optional_number(p.recall), optional_number(p.f1),
                     optional_number(p.fpr)});
  }
  json graph = json::array();
  for (const auto& e : run.evaluation.matching_graph) {
    graph.push_back({e.query, e.match, number(e.distance), static_cast<int>(e.label)});
  }
  json training = nullptr;
  if (run.training) {
    training = {{"sequence", run.training->sequence},
                {"scans", run.training->scans},
                {"loaded", run.training->loaded},
                {"seconds", number(run.training->seconds)},
                {"from_cache", run.training->from_cache},
                {"codebook_sha256", run.training->codebook_sha256}};
  }
  json codebook = nullptr;
  if (run.codebook) {
    codebook = {{"sha256", run.codebook->sha256},
                {"loaded_from", run.codebook->loaded_from},
                {"saved_to", run.codebook->saved_to}};
  }
  return {{"id", run.id},
          {"label", run.label},
          {"rows", run.rows},
          {"cols", run.cols},
          {"payload_bytes", run.payload_bytes},
          {"paper_bytes", run.paper_bytes},
          {"rotation_invariant", run.rotation_invariant},
          {"mean_extract_ms", number(run.mean_extract_ms)},
          {"query_values_cached", run.query_values_cached},
          {"database_values_cached", run.database_values_cached},
          {"training", training},
          {"codebook", codebook},
          {"metrics", metrics_to_json(run.evaluation.metrics)},
          {"results", results},
          {"curve", curve},
          {"matching_graph", graph},
          {"ranked_frames", run.evaluation.ranked_frames}};
}

DescriptorRun descriptor_run_from_json(const nlohmann::json& j) {
  try {
    DescriptorRun run;
    run.id = field(j, "id").get<std::string>();
    run.label = field(j, "label").get<std::string>();
    run.rows = field(j, "rows").get<int>();
    run.cols = field(j, "cols").get<int>();
    run.payload_bytes = field(j, "payload_bytes").get<std::size_t>();
    run.paper_bytes = field(j, "paper_bytes").get<std::size_t>();
    run.rotation_invariant = field(j, "rotation_invariant").get<bool>();
    run.mean_extract_ms = read_number(field(j, "mean_extract_ms"));
    run.query_values_cached = field(j, "query_values_cached").get<bool>();
    run.database_values_cached = field(j, "database_values_cached").get<bool>();
    // Absent in a unit written before the Recall@N curve: 0, no ranks known beyond K.
    run.evaluation.ranked_frames = j.value("ranked_frames", std::size_t{0});
    const json& training = field(j, "training");
    if (!training.is_null()) {
      run.training = TrainingRecord{field(training, "sequence").get<std::string>(),
                                    field(training, "scans").get<std::size_t>(),
                                    field(training, "loaded").get<std::size_t>(),
                                    read_number(field(training, "seconds")),
                                    field(training, "from_cache").get<bool>(),
                                    field(training, "codebook_sha256").get<std::string>()};
    }
    const json& codebook = field(j, "codebook");
    if (!codebook.is_null()) {
      run.codebook = CodebookRecord{field(codebook, "sha256").get<std::string>(),
                                    field(codebook, "loaded_from").get<std::string>(),
                                    field(codebook, "saved_to").get<std::string>()};
    }
    run.evaluation.metrics = metrics_from_json(field(j, "metrics"));
    for (const auto& r : field(j, "results")) {
      run.evaluation.results.push_back({r.at(0).get<std::size_t>(), r.at(1).get<std::size_t>(),
                                        read_number(r.at(2)), r.at(3).get<bool>(),
                                        r.at(4).get<bool>(), r.at(5).get<std::size_t>()});
    }
    for (const auto& p : field(j, "curve")) {
      CurvePoint point;
      point.threshold = read_number(p.at(0));
      point.counts = {p.at(1).get<std::size_t>(), p.at(2).get<std::size_t>(),
                      p.at(3).get<std::size_t>(), p.at(4).get<std::size_t>()};
      point.precision = read_optional(p.at(5));
      point.recall = read_optional(p.at(6));
      point.f1 = read_optional(p.at(7));
      point.fpr = read_optional(p.at(8));
      run.evaluation.curve.push_back(point);
    }
    for (const auto& e : field(j, "matching_graph")) {
      const int label = e.at(3).get<int>();
      if (label < 0 || label > 2) throw std::runtime_error("descriptor result: bad graph label");
      run.evaluation.matching_graph.push_back({e.at(0).get<std::size_t>(),
                                               e.at(1).get<std::size_t>(), read_number(e.at(2)),
                                               static_cast<GraphLabel>(label)});
    }
    return run;
  } catch (const nlohmann::json::exception& error) {
    throw std::runtime_error(fmt::format("descriptor result: {}", error.what()));
  }
}

}  // namespace radarpr
