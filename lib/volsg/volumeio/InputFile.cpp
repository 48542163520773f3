#include <volsg/volumeio/InputFile.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <volsg/core/Error.h>
#include <volsg/io/ContainedFile.h>

namespace volsg {

InputFile::InputFile(std::string path) : path_(std::move(path)) {
    std::error_code ec;
    const auto status = std::filesystem::status(path_, ec);
    if (ec || !std::filesystem::exists(status))
        fail("cannot open volume file: " +
             (ec ? ec.message() : std::string("No such file or directory")));
    // fopen() succeeds on a directory; the read would then fail with a less helpful message.
    if (!std::filesystem::is_regular_file(status))
        fail("cannot open volume file: not a regular file");
    file_ = std::fopen(path_.c_str(), "rb");
    if (!file_) fail(std::string("cannot open volume file: ") + std::strerror(errno));
    if (fseeko(file_, 0, SEEK_END) != 0) fail(std::string("cannot seek: ") + std::strerror(errno));
    const off_t end = ftello(file_);
    if (end < 0 || fseeko(file_, 0, SEEK_SET) != 0)
        fail(std::string("cannot determine the file size: ") + std::strerror(errno));
    size_ = std::uint64_t(end);
}

InputFile::~InputFile() {
    if (file_) std::fclose(file_);
}

std::uint64_t InputFile::position() const {
    const off_t p = ftello(file_);
    if (p < 0) fail(std::string("cannot tell the file position: ") + std::strerror(errno));
    return std::uint64_t(p);
}

void InputFile::seek(std::uint64_t offset) {
    if (offset > size_)
        fail("offset " + std::to_string(offset) + " is past the end of the file (" +
             std::to_string(size_) + " bytes)");
    if (fseeko(file_, off_t(offset), SEEK_SET) != 0)
        fail(std::string("cannot seek: ") + std::strerror(errno));
}

std::size_t InputFile::read(void* destination, std::size_t count) {
    const std::size_t got = std::fread(destination, 1, count, file_);
    if (got < count && std::ferror(file_)) fail(std::string("read error: ") + std::strerror(errno));
    return got;
}

int InputFile::getByte() {
    const int c = std::getc(file_);
    if (c == EOF && std::ferror(file_)) fail(std::string("read error: ") + std::strerror(errno));
    return c == EOF ? -1 : c;
}

void InputFile::skipLines(std::uint64_t count) {
    for (std::uint64_t seen = 0; seen < count;) {
        const int c = getByte();
        if (c < 0)
            fail("line skip of " + std::to_string(count) + " passes the end of the file after " +
                 std::to_string(seen) + " lines");
        if (c == '\n') ++seen;
    }
}

std::string InputFile::resolveBeside(const std::string& headerPath, const std::string& name) {
    return containedFile(headerPath, name);
}

void InputFile::fail(const std::string& message, int line) const {
    throw Error(message, path_, line);
}

std::unique_ptr<InputFile> InputFile::openDataFile(const std::string& headerPath,
                                                   const std::string& name) {
    try {
        return std::make_unique<InputFile>(resolveBeside(headerPath, name));
    } catch (const Error& e) {
        throw Error(e.message() + " (the data file named in " + headerPath + ")", e.file(),
                    e.line(), e.column());
    }
}

} // namespace volsg
