// Writes snapshots to OUTDIR/trajectory.h5 (layout in docs/output.md) and keeps
// OUTDIR/trajectory.xdmf beside it up to date so ParaView can open the series at any time.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "io/xdmf.hpp"
#include "sim/frame.hpp"

namespace cortex {

class TrajectoryWriter : public FrameWriter {
 public:
  // Without `append`, creates trajectory.h5 afresh. With `append` (a resumed run), reopens it
  // and deletes the snapshots numbered >= first_index, which the resumed run writes again.
  // Throws InputError if `append` and the file cannot be opened.
  TrajectoryWriter(std::filesystem::path outdir, std::int64_t first_index, bool append);

  // Writes snapshot nextIndex() and closes the file again, so a crash never leaves it
  // half-open: every completed snapshot stays readable. Then rewrites the XDMF.
  void write(const Frame& frame) override;

  std::int64_t nextIndex() const { return next_index_; }

 private:
  std::filesystem::path h5Path() const;
  void writeXdmf() const;

  std::filesystem::path outdir_;
  std::int64_t next_index_;
  std::vector<XdmfSnapshot> snapshots_;  // what the file holds, to regenerate the XDMF
};

}  // namespace cortex
