// The fixed measures [px] of a LinePlot's layout, shared by its layout and its renderer.
#pragma once

namespace usvid::line_plot_metrics {

inline constexpr double kPad = 10.0;             // canvas edge to the outermost text
inline constexpr double kTickFont = 11.0;        // tick labels
inline constexpr double kLabelFont = 12.5;       // axis labels
inline constexpr double kAnnotationFont = 11.0;  // band and reference-line labels
inline constexpr double kAnnotationRow = 15.0;   // height of one row of those labels
inline constexpr double kTickGap = 6.0;          // plot-area edge to tick labels
inline constexpr double kLabelGap = 6.0;         // tick labels to axis label
inline constexpr double kLegendGap = 16.0;       // plot area to legend
inline constexpr double kMinArea = 20.0;         // smallest plot-area side
inline constexpr double kYTickSpacing = 30.0;    // at least this much between y ticks
inline constexpr double kXTickGap = 14.0;        // at least this much between x tick labels

}  // namespace usvid::line_plot_metrics
