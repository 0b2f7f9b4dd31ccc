#include "drum/io/atomicFile.hpp"

#include "drum/io/inputError.hpp"

#include <cerrno>
#include <cstring>
#include <system_error>
#include <unistd.h>

namespace drum
{

AtomicFile::AtomicFile(std::filesystem::path target)
:
    target_(std::move(target)),
    temp_(target_.parent_path()
        / ("." + target_.filename().string() + ".tmp" + std::to_string(::getpid())))
{
    if (std::filesystem::is_directory(target_))
    {
        throw std::runtime_error("cannot write " + target_.string() + ": it is a folder, not a file");
    }
    if (!target_.parent_path().empty())
    {
        std::error_code ec;
        std::filesystem::create_directories(target_.parent_path(), ec);
        if (ec)
        {
            throw std::runtime_error("cannot write " + target_.string() + ": cannot make its folder ("
                                     + ec.message() + ")");
        }
    }
    out_.open(temp_);
    if (!out_)
    {
        throw std::runtime_error("cannot write " + target_.string() + ": " + std::strerror(errno)
                                 + " (folder not writable or disk full?)");
    }
    out_.precision(10);
}

AtomicFile::~AtomicFile()
{
    if (!committed_)
    {
        out_.close();
        std::error_code ec;
        std::filesystem::remove(temp_, ec);
    }
}

void AtomicFile::commit()
{
    // a full disk shows as a failed write, flush or close, or a short file
    out_.flush();
    const std::streamoff size = out_ ? std::streamoff(out_.tellp()) : -1;
    out_.close();
    std::error_code ec;
    if (!out_ || size < 0 || std::streamoff(std::filesystem::file_size(temp_, ec)) != size || ec)
    {
        throw std::runtime_error("cannot write " + target_.string() + " (writing its temporary "
                                 + temp_.string() + " failed: disk full or not writable?)");
    }
    std::filesystem::rename(temp_, target_);
    committed_ = true;
}

void writeFileAtomically(const std::filesystem::path& path, const std::string& text)
{
    AtomicFile f(path);
    f.stream() << text;
    f.commit();
}

} // namespace drum
