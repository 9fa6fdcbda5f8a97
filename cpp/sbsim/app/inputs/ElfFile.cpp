#include "sbsim/app/inputs/ElfFile.h"

#include <elf.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <vector>

#include "sbsim/app/cli/BadInput.h"

namespace sbsim::app {

namespace {

static_assert(sizeof(void*) == 8, "sbsim's plugins are 64-bit ELF files");
#if defined(__x86_64__)
constexpr Elf64_Half kMachine = EM_X86_64;
#elif defined(__aarch64__)
constexpr Elf64_Half kMachine = EM_AARCH64;
#else
#error "add this machine's ELF e_machine value"
#endif
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
constexpr unsigned char kByteOrder = ELFDATA2LSB;
#else
constexpr unsigned char kByteOrder = ELFDATA2MSB;
#endif

/// Whether [offset, offset + count * size) lies within a file of `fileSize` bytes, without overflow.
bool within(std::uint64_t offset, std::uint64_t count, std::uint64_t size, std::uint64_t fileSize) {
    if (offset > fileSize) return false;
    return size == 0 || count <= (fileSize - offset) / size;
}

/// Closes the descriptor however the check ends.
struct Descriptor {
    int fd;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

void requireLoadableElf(const std::string& option, const std::filesystem::path& path) {
    const auto bad = [&](const std::string& why) {
        return InputError(fmt::format("{}: cannot load '{}': {}", option, path.string(), why));
    };
    const Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
    struct stat info {};
    if (file.fd < 0 || ::fstat(file.fd, &info) != 0) throw bad(std::strerror(errno));
    const auto fileSize = static_cast<std::uint64_t>(info.st_size);

    Elf64_Ehdr header{};
    if (::pread(file.fd, &header, sizeof header, 0) != static_cast<ssize_t>(sizeof header) ||
        std::memcmp(header.e_ident, ELFMAG, SELFMAG) != 0) {
        throw bad("not an ELF shared library");
    }
    if (header.e_ident[EI_CLASS] != ELFCLASS64 || header.e_ident[EI_DATA] != kByteOrder ||
        header.e_machine != kMachine) {
        throw bad("an ELF file for another kind of machine");
    }
    if (header.e_type != ET_DYN) throw bad("an ELF file but not a shared library");
    if (header.e_phentsize != sizeof(Elf64_Phdr) || header.e_phnum == 0 ||
        !within(header.e_phoff, header.e_phnum, sizeof(Elf64_Phdr), fileSize) ||
        (header.e_shoff != 0 && !within(header.e_shoff, header.e_shnum, header.e_shentsize, fileSize))) {
        throw bad("a damaged or truncated ELF file (its headers run past its end)");
    }
    std::vector<Elf64_Phdr> segments(header.e_phnum);
    const auto bytes = static_cast<ssize_t>(segments.size() * sizeof(Elf64_Phdr));
    if (::pread(file.fd, segments.data(), static_cast<std::size_t>(bytes), static_cast<off_t>(header.e_phoff)) !=
        bytes) {
        throw bad("cannot read its program headers");
    }
    for (const Elf64_Phdr& segment : segments) {
        if ((segment.p_type == PT_LOAD || segment.p_type == PT_DYNAMIC) &&
            !within(segment.p_offset, 1, segment.p_filesz, fileSize)) {
            throw bad("a truncated ELF file (a segment runs past its end)");
        }
    }
}

}  // namespace sbsim::app
