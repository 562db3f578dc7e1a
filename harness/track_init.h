// A first track file for a vessel folder (`usvid init-track DIR/NAME --data FILE`; docs/tracks.md):
// the columns of one log's header that usvid recognises, mapped to its channels, and the rest
// listed for the person to map, as comments in the file it writes.
#pragma once

#include <string>
#include <vector>

namespace usvid {

struct RecognisedColumns {
  // channel -> the column (with ":deg" where the header marks degrees), in the channels' order
  std::vector<std::pair<std::string, std::string>> mapped;
  std::vector<std::string> unmapped;  // the header's other columns
};

// The channels the header `columns` holds, by their usual names in logs (t, time; psi, heading,
// psi_hat; delta, rudder; x0, x_position; speed, sog; ...), each channel from its first match.
RecognisedColumns RecogniseColumns(const std::vector<std::string>& columns);

// The text of a first track.yaml for `name` with the runs' `columns` recognised (format
// csv-log): the columns mapped, r from psi when no column holds it, the runs read from the folder
// and every folder below it, every run held out in turn; comments say what to check.
std::string TrackFileText(const std::string& name, const RecognisedColumns& columns,
                          const std::string& log, bool has_vessel);

}  // namespace usvid
