// An HDF5 file driver that makes every flush of a growing file atomic, so that a run killed at any
// moment (SIGKILL, a crash) leaves its `.partial` snapshot and fields files as they were at one
// flush or the next, never a mixture.
//
// Why: HDF5 updates its metadata (chunk indices, object headers, the superblock's end of file) in
// place, entry by entry, when it flushes.  A run killed in the middle of a flush left a chunk
// index pointing to a node not yet written ("wrong B-tree signature") and the run could not be
// resumed (a stress test of SIGKILLs at random moments broke the file in about one kill in two
// when frames were written often).
//
// How: raw data (H5FD_MEM_DRAW) goes to the file at once, always into space that nothing on disk
// refers to yet (the files only grow between flushes).  Metadata writes are held in memory until
// HDF5 ends its flush (the driver's flush or truncate callback), then committed as a redo log:
// written whole to `<file>.journal` (atomically: temporary name, fsync, rename), applied to the
// file, the file synced, the journal removed.  Whoever opens the file next, this driver or
// `replay_journal`, applies a journal left behind first.  Reads see the held writes.
// The files keep the canonical HDF5 format: any reader (h5py, h5dump) opens them.
#pragma once

#include <hdf5.h>

#include <string>

namespace granule::h5 {

// The driver's id, registered with HDF5 on first use (for H5Pset_driver).
hid_t journaled_file_driver();

// Applies `<path>.journal` to `path` if a commit left one behind, and removes an incomplete
// `<path>.journal.tmp`.  Throws IoError if the journal is damaged or cannot be applied.
void replay_journal(const std::string& path);

}  // namespace granule::h5
