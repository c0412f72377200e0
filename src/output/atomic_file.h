// The one way result files are written: to a hidden temporary name in the destination folder
// (".NAME.tmpPID"), flushed, then renamed over the final name. rename is atomic within one file
// system, so a reader never sees a half-written file, even if the run is killed while writing.
// And the one way a file is read back whole (to embed a picture, or compare a saved text).
#ifndef DRAPE_SRC_OUTPUT_ATOMIC_FILE_H_
#define DRAPE_SRC_OUTPUT_ATOMIC_FILE_H_

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace drape {

// `write` fills the file at the temporary path it is given (for writers that open files
// themselves, such as cairo's PNG writer). Throws std::runtime_error naming the file on failure;
// the temporary is removed.
void WriteFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path&)>& write);

// The same for text and binary streams: `write` writes into an open std::ofstream.
void WriteAtomically(const std::filesystem::path& path,
                     const std::function<void(std::ostream&)>& write);

// The bytes of the file at `path`; empty when it cannot be read.
std::string ReadWholeFile(const std::filesystem::path& path);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_ATOMIC_FILE_H_
