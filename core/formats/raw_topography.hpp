// What a topography file holds before the project turns it into a Surface: named channels, each a grid of
// values in metres with NaN where the instrument measured nothing (docs/formats.md).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench::formats {

struct Channel {
  std::string name;
  // Heights (lengths) or something else (phase, amplitude): only height channels become surfaces.
  bool is_height = true;
  std::string unit;  // the file's unit for the values, for messages (heights are stored in metres)
  Index nx = 0;      // points along x (fast index)
  Index ny = 0;      // points along y
  // Lateral sizes [m] when the file carries them (NumPy arrays do not).
  std::optional<Real> lx;
  std::optional<Real> ly;
  // ny x nx values, row-major (row = y), in metres; NaN marks an invalid (unmeasured) point.
  std::vector<Real> values;
};

inline Channel make_channel(std::string name, bool is_height, std::string unit, Index nx, Index ny) {
  Channel channel;
  channel.name = std::move(name);
  channel.is_height = is_height;
  channel.unit = std::move(unit);
  channel.nx = nx;
  channel.ny = ny;
  return channel;
}

struct RawTopography {
  std::vector<Channel> channels;
  bool periodic = false;  // as the file states it (NetCDF may), else false
};

}  // namespace contactbench::formats
