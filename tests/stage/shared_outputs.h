#pragma once
// Outputs that several stage-test processes need alike (the samples' pipeline up to
// strands.h5, a styles.h5, a short simulation): ctest runs every test in a process of
// its own, so without sharing each process would make them again.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace hair::test {

/// The programs, models and samples the shared outputs are made from, as one line per
/// file (name, size, modification time): outputs made under another stamp are made again.
std::string build_stamp();

/// Puts the files `names` into `folder`. Those missing there are copied from a folder
/// shared by the stage tests of this build (tests/shared_outputs/<key>), where `make`
/// writes them into the folder it is given the first time any process asks for `key`
/// after the programs were built; a lock makes a second process wait for the first.
/// `make` must be deterministic in `key`. A failure inside `make` (a gtest assertion)
/// is reported and nothing is shared.
void shared_outputs(const std::string& key, const std::filesystem::path& folder,
                    const std::vector<std::string>& names,
                    const std::function<void(const std::filesystem::path&)>& make);

}  // namespace hair::test
