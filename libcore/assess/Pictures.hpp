// The pictures hvi-assess draws for a designer (docs/metrics.md, "Pictures"):
//
//   material_tT.TTTus.png   bodies (SPH particles and FE elements) coloured by body, mirrored
//                           about the axis, with a scale bar and the time
//   damage_tT.TTTus.png     the same coloured by damage D (viridis, 0..1)
//   rear_wall_damage.png    failed fraction and mean damage of the rear wall against radius,
//                           at the last snapshot
//   energy.png              kinetic, internal, total and total + deleted energy against time
//   energy_error.png        the relative energy error against time
//   momentum.png            axial momentum against time
//
// All PNGs have the same pixel size (PictureOptions). Every picture of a run uses the same
// view, so pictures at different times can be compared frame by frame.
#pragma once

#include "assess/Assessment.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace hvi::assess {

struct PictureOptions {
    std::string directory;
    int widthPx = 1200, heightPx = 800;
    /// zMin, zMax, rMax [mm]; default: the bodies and the debris, see viewOf().
    std::optional<std::array<double, 3>> view;
};

/// The snapshots nearest to each of `timesUs` (deduplicated, in time order). With no times:
/// four times evenly spaced up to the last snapshot (t_last/4, t_last/2, 3 t_last/4, t_last).
std::vector<int> pictureSnapshots(const std::vector<io::SnapshotInfo>& snapshots,
                                  const std::vector<double>& timesUs);

/// Draws the pictures of the snapshots `indices` (which must be among assessment.kept) and
/// the run-level plots into options.directory (created if needed). Returns the files
/// written. Throws RuntimeFailure when a file cannot be written.
std::vector<std::string> writePictures(const Assessment& assessment,
                                       const std::vector<int>& indices,
                                       const PictureOptions& options);

} // namespace hvi::assess
