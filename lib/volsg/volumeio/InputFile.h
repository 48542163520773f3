#pragma once
// A read-only binary file with its size known up front, for the volume readers.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

namespace volsg {

/// Opens `path` for reading or throws volsg::Error naming it ("cannot open volume file: No such
/// file or directory"). Offsets are 64-bit. Reads never allocate.
class InputFile {
public:
    explicit InputFile(std::string path);
    ~InputFile();
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;

    const std::string& path() const { return path_; }
    std::uint64_t size() const { return size_; }
    std::uint64_t position() const;
    void seek(std::uint64_t offset); ///< throws past the end of the file

    /// Up to `count` bytes into `destination`; fewer only at the end of the file.
    std::size_t read(void* destination, std::size_t count);
    int getByte(); ///< the next byte, or -1 at the end of the file
    /// Moves past `count` newline characters; throws when the file ends first.
    void skipLines(std::uint64_t count);

    [[noreturn]] void fail(const std::string& message, int line = 0) const;

    /// `name` as written in the header at `headerPath`, resolved against the header's folder;
    /// it must lie inside that folder (io/ContainedFile.h), else an Error naming the header.
    static std::string resolveBeside(const std::string& headerPath, const std::string& name);

    /// Opens the data file `name` of the header at `headerPath` (resolveBeside); an error
    /// names the data file and says which header named it.
    static std::unique_ptr<InputFile> openDataFile(const std::string& headerPath,
                                                   const std::string& name);

private:
    std::string path_;
    std::FILE* file_ = nullptr;
    std::uint64_t size_ = 0;
};

} // namespace volsg
