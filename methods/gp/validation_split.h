// Where GP validates: the last share of the record, on which model selection and the
// simulation refit's check run (model_selection.h, simulation_refit.h). Records joined for one
// fit, or a record with gaps (core/stretches.h), are validated on the last share of each
// stretch, not of the last one alone: the rows are reordered, every stretch's first part first,
// then every stretch's last part, each piece after a gap (core/records.h), so that the
// validation rows are again the last rows and no simulation runs from one piece into the next.
#pragma once

#include <optional>

#include "preprocessing/pipeline.h"

namespace usvid::gp {

struct ValidationSplit {
  std::optional<PreparedData> reordered;  // none: one stretch, which stays as it is
  long train_rows = 0;                    // the first part's rows, when reordered
};

// The split for the validation share `f` (0: none). A stretch too short to leave two rows on
// each side stays whole in the first part.
ValidationSplit SplitForValidation(const PreparedData& prepared, double f);

}  // namespace usvid::gp
