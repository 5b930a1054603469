#include "evaluation/protocol.hpp"

namespace radarpr {

// The names below are the ones result files and configs use (protocols.md).

std::string_view to_string(LabelRule rule) {
  switch (rule) {
    case LabelRule::standard:
      return "standard";
    case LabelRule::retrieved_pair:
      return "retrieved_pair";
  }
  return "unknown";
}

std::string_view to_string(ThresholdSweep sweep) {
  switch (sweep) {
    case ThresholdSweep::exact:
      return "exact";
    case ThresholdSweep::linear100:
      return "linear100";
    case ThresholdSweep::mulran_grid:
      return "mulran_grid";
  }
  return "unknown";
}

std::string_view to_string(TrainingSource source) {
  switch (source) {
    case TrainingSource::database:
      return "database";
    case TrainingSource::training_sequence:
      return "training_sequence";
  }
  return "unknown";
}

std::optional<TrainingSource> parse_training_source(std::string_view text) {
  for (const TrainingSource source :
       {TrainingSource::database, TrainingSource::training_sequence}) {
    if (text == to_string(source)) return source;
  }
  return std::nullopt;
}

std::optional<LabelRule> parse_label_rule(std::string_view text) {
  for (const LabelRule rule : {LabelRule::standard, LabelRule::retrieved_pair}) {
    if (text == to_string(rule)) return rule;
  }
  return std::nullopt;
}

std::optional<ThresholdSweep> parse_threshold_sweep(std::string_view text) {
  for (const ThresholdSweep sweep :
       {ThresholdSweep::exact, ThresholdSweep::linear100, ThresholdSweep::mulran_grid}) {
    if (text == to_string(sweep)) return sweep;
  }
  return std::nullopt;
}

}  // namespace radarpr
