#pragma once
/// An --out directory that a run writes frames into must hold that run's frames only: a second
/// `tecido run --out DIR` of fewer steps or another --frame-every would otherwise leave the first
/// run's frames beside its own, and a viewer would play both. Before its first frame, the run
/// removes the frame files of an earlier run, recognised by tecido's own naming (frame_writer.h:
/// frame_<step, at least 6 digits>.obj|.vtk) and nothing else.
#include <cstddef>
#include <string>

namespace tecido::io {

/// Whether `name` (a file name, no directory) is one FrameWriter writes.
bool is_frame_file_name(const std::string& name);

/// Removes from `dir` the regular files whose names are frame names (no other file, no link, no
/// subdirectory, nothing below it); returns how many. A missing `dir` holds none. A file that
/// cannot be removed is an OutputError naming it.
std::size_t remove_stale_frames(const std::string& dir);

}  // namespace tecido::io
