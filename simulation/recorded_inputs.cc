#include "simulation/recorded_inputs.h"

#include "core/error.h"

namespace usvid {

InputTrack RecordedInputs(const Dataset& data, const VesselInfo& info) {
  const auto inputs = static_cast<int>(info.inputs.size());
  std::vector<const Channel*> channels;
  for (size_t i = 0; i < info.inputs.size(); ++i) {
    const std::string& name = info.inputs[i];
    const Channel* c = data.Find(name);
    if (c == nullptr && info.IsMeasuredInput(i)) {
      channels.push_back(nullptr);  // no wind logged: none
      continue;
    }
    if (c == nullptr)
      throw InputError(data.SourcePrefix() + "no input column '" + name + "' for vessel " +
                       info.name);
    channels.push_back(c);
  }
  std::vector<double> u(inputs, 0.0);
  for (int i = 0; i < inputs; ++i) {
    if (channels[i] == nullptr) u[i] = info.actuation.neutral.at(i);
    for (Eigen::Index k = 0; k < data.rows() && channels[i] != nullptr; ++k)
      if (channels[i]->IsSampled(k)) {
        u[i] = channels[i]->Value(k);
        break;
      }
  }
  InputTrack track(inputs);
  for (Eigen::Index k = 0; k < data.rows(); ++k) {
    for (int i = 0; i < inputs; ++i)
      if (channels[i] != nullptr && channels[i]->IsSampled(k)) u[i] = channels[i]->Value(k);
    track.Append(data.t()(k), u);
  }
  return track;
}

}  // namespace usvid
