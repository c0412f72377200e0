// The one way result files are written: to a hidden temporary name in the destination folder
// (".NAME.tmpPID"), flushed, then renamed over the final name. rename is atomic within one file
// system, so a reader never sees a half-written file, even if the run is killed while writing.
#ifndef DRAPE_SRC_OUTPUT_ATOMIC_FILE_H_
#define DRAPE_SRC_OUTPUT_ATOMIC_FILE_H_

#include <filesystem>
#include <functional>
#include <ostream>

namespace drape {

// `write` fills the file at the temporary path it is given (for writers that open files
// themselves, such as cairo's PNG writer). Throws std::runtime_error naming the file on failure;
// the temporary is removed.
void WriteFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path&)>& write);

// The same for text and binary streams: `write` writes into an open std::ofstream.
void WriteAtomically(const std::filesystem::path& path,
                     const std::function<void(std::ostream&)>& write);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_ATOMIC_FILE_H_
