// The names of the files and folders limber leaves in a run directory, spelt once: the writer
// of each file and every reader (render, report, sweep, select) build paths from these.
// Formats: docs/results-format.md, docs/modes-format.md, docs/rendering.md, docs/report.md,
// docs/sweep.md, docs/select.md.
#pragma once

namespace limber::results {

// `limber run`: the results (docs/results-format.md).
inline constexpr const char* kResultsFileName = "results.h5";
// `limber modes`: the mode sets (docs/modes-format.md).
inline constexpr const char* kModesFileName = "modes.h5";

// `limber render`: DIR/frames/frame_00000.png ..., DIR/animation.mp4|gif, DIR/vtk/scene.pvd.
inline constexpr const char* kFramesFolder = "frames";
inline constexpr const char* kFramePrefix = "frame_";
inline constexpr const char* kAnimationVideoFileName = "animation.mp4";
inline constexpr const char* kAnimationGifFileName = "animation.gif";
inline constexpr const char* kVtkFolder = "vtk";
inline constexpr const char* kVtkSceneFileName = "scene.pvd";

// `limber report`: DIR/report/index.html by default.
inline constexpr const char* kReportFolder = "report";
inline constexpr const char* kReportIndexFileName = "index.html";

// `limber select`: DIR/selection/{ranking,comparison,key_series,event_peaks}.csv.
inline constexpr const char* kSelectionFolder = "selection";
inline constexpr const char* kRankingFileName = "ranking.csv";
inline constexpr const char* kComparisonFileName = "comparison.csv";
inline constexpr const char* kKeySeriesFileName = "key_series.csv";
inline constexpr const char* kEventPeaksFileName = "event_peaks.csv";

// `limber sweep`: DIR/sweep/{work_precision.csv,work_precision.json,errors.csv}; each point's
// run in DIR/runs/<point>/ with the run's JSON summary, its log and the process record.
inline constexpr const char* kSweepFolder = "sweep";
inline constexpr const char* kWorkPrecisionFileName = "work_precision.csv";
inline constexpr const char* kWorkPrecisionJsonFileName = "work_precision.json";
inline constexpr const char* kErrorsFileName = "errors.csv";
inline constexpr const char* kRunsFolder = "runs";
inline constexpr const char* kRunJsonFileName = "run.json";
inline constexpr const char* kRunLogFileName = "run.log";
inline constexpr const char* kProcessJsonFileName = "process.json";

}  // namespace limber::results
