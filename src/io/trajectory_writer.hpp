// Writes snapshots and keeps the trajectory readable after a crash at any moment: each
// snapshot is its own HDF5 file, OUTDIR/snapshots/NNNNNN.h5, built in memory and written
// atomically; OUTDIR/trajectory.h5 is an index whose groups /snapshots/NNNNNN are
// external links to those files (h5py and ParaView follow them; layout in
// docs/output.md), rewritten atomically after each snapshot with trajectory.xdmf. A
// snapshot appears in the index only once its file is whole. The index also holds the
// observables of every snapshot as one table (/observables), written as observables.csv
// too.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "io/observables.hpp"
#include "io/xdmf.hpp"
#include "sim/frame.hpp"

namespace cortex {

class TrajectoryWriter : public FrameWriter {
 public:
  // A fresh run (append = false) starts an empty trajectory. A resumed one keeps the
  // snapshot files numbered below first_index, deletes later ones and any temporary file
  // a crash left, and rebuilds the index. `run_id` is stored in the index.
  // `config_toml`, the effective config, is stored in the index with the version and units.
  TrajectoryWriter(std::filesystem::path outdir, std::int64_t first_index, bool append, std::string run_id,
                   std::string config_toml);

  // Writes snapshot nextIndex(), then the index and the XDMF.
  void write(const Frame& frame) override;

  std::int64_t nextIndex() const { return next_index_; }

 private:
  void writeIndex() const;

  std::filesystem::path outdir_;
  std::int64_t next_index_;
  std::string run_id_, config_toml_;
  std::vector<XdmfSnapshot> snapshots_;  // what the index lists
  std::vector<ObservableRow> rows_;      // their observables, in the same order
};

// The run id stored in OUTDIR/trajectory.h5; empty if it has none or cannot be read.
std::string trajectoryRunId(const std::filesystem::path& outdir);

}  // namespace cortex
