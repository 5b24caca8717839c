// Writes snapshots and keeps the trajectory readable after a crash at any moment: each
// snapshot is its own HDF5 file, OUTDIR/snapshots/NNNNNN.h5, built in memory and written
// atomically; OUTDIR/trajectory.h5 is an index whose groups /snapshots/NNNNNN are
// external links to those files (h5py and ParaView follow them; layout in
// docs/output.md), rewritten atomically with trajectory.xdmf. A snapshot appears in the
// index only once its file is whole. Rewriting costs in proportion to the snapshots so
// far: after the first 100 the index waits until its writing would be at most 1/20 of the
// time since it was last written (2,000 snapshots of a small run took 29 s, and 4,000 over
// two minutes, when it was rewritten after each), and flush() brings it up to date when
// the run ends, fails or stops. After a kill it may lag; a resume rebuilds it from the
// snapshot files. The index also holds the
// observables of every snapshot as one table (/observables), written as observables.csv
// too, and what a reader needs to interpret the datasets (units, version, config, the
// compartment grid, species and type names) as root attributes. The compartment grid's
// corner points, which never move, are written once to OUTDIR/compartments.h5 for the XDMF.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "io/observables.hpp"
#include "io/xdmf.hpp"
#include "sim/frame.hpp"

namespace cortex {

// What the index's root attributes say about the datasets, from the latest snapshot.
struct DatasetNames {
  double compartment_size = 0.0;                // nm; 0 without compartments
  std::vector<std::int64_t> compartment_shape;  // empty without compartments
  std::vector<std::string> species;             // compartment species
  std::vector<std::string> filament_types, linker_types, motor_types;
};

class TrajectoryWriter : public FrameWriter {
 public:
  // A fresh run (append = false) starts an empty trajectory. A resumed one keeps the
  // snapshot files numbered below first_index, deletes later ones and any temporary file
  // a crash left, and rebuilds the index. `run_id` is stored in the index.
  // `config_toml`, the effective config, is stored in the index with the version and units.
  TrajectoryWriter(std::filesystem::path outdir, std::int64_t first_index, bool append, std::string run_id,
                   std::string config_toml);

  // Before a resume writes anything (read-only): the checkpoint counts at least snapshot
  // 0, the snapshot files 0 .. first_index − 1 are all there and this run's (`run_id`), and they end where the checkpoint of
  // `checkpoint_time` does (the last of them no later, the next, if any, later). Throws
  // InputError otherwise. The constructor then keeps those and replaces the rest.
  static void checkResumable(const std::filesystem::path& outdir, std::int64_t first_index, const std::string& run_id,
                             double checkpoint_time);

  // Writes snapshot nextIndex(), then (see above) the index and the XDMF.
  void write(const Frame& frame) override;
  // Writes the index and the XDMF if a snapshot is not listed yet.
  void flush();

  std::int64_t nextIndex() const { return next_index_; }

 private:
  void writeIndex();
  void writeCompartmentPoints(const Frame& frame);

  std::filesystem::path outdir_;
  std::int64_t next_index_;
  std::string run_id_, config_toml_;
  std::vector<XdmfSnapshot> snapshots_;  // what the index lists
  std::vector<ObservableRow> rows_;      // their observables, in the same order
  DatasetNames names_;
  bool compartment_points_written_ = false;
  std::size_t indexed_ = 0;  // snapshots the index on disk lists
  std::chrono::steady_clock::time_point index_written_;
  double index_seconds_ = 0.0;  // how long the last index took to write
};

// The run id stored in OUTDIR/trajectory.h5; empty if it has none or cannot be read.
std::string trajectoryRunId(const std::filesystem::path& outdir);

}  // namespace cortex
