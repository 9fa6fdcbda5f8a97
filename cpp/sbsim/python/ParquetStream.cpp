#include "sbsim/python/ParquetStream.h"

#include <fcntl.h>
#include <pybind11/embed.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <nlohmann/json.hpp>

extern char** environ;

namespace py = pybind11;

namespace sbsim::python {

namespace {

// The child: reads row groups (an 8-byte length, a JSON header, the columns' Arrow buffers) on
// stdin and writes them to descriptor 3 with pyarrow's ParquetWriter; answers one line per
// step on stdout ("ready", "ok <bytes>", "done <bytes>" or "error <why>"). End of input closes the
// file; a parent gone half-way through a row group leaves what was written before it.
constexpr const char* kChild = R"(
import io, json, os, signal, sys
for s in (signal.SIGINT, signal.SIGTERM):
    signal.signal(s, signal.SIG_IGN)
def say(*words):
    sys.stdout.write(" ".join(str(w) for w in words).replace("\n", " ") + "\n")
    sys.stdout.flush()
try:
    import pyarrow as pa, pyarrow.parquet as pq
except Exception as e:
    say("error", f"{type(e).__name__}: {e}")
    sys.exit(1)
class Sink(io.RawIOBase):
    def __init__(self, f):
        self.f, self.n = f, 0
    def writable(self):
        return True
    def write(self, b):
        self.f.write(b)
        self.n += len(b)
        return len(b)
    def tell(self):
        return self.n
    def flush(self):
        self.f.flush()
say("ready")
src = sys.stdin.buffer
def exact(n):
    b = src.read(n)
    if b is None or len(b) < n:
        raise EOFError
    return b
types = {"f8": pa.float64(), "i8": pa.int64(), "str": pa.string()}
sink = Sink(os.fdopen(3, "wb", buffering=1 << 20, closefd=False))
writer = None
try:
    while True:
        head = src.read(8)
        if not head:
            break
        if len(head) < 8:
            raise EOFError
        meta = json.loads(exact(int.from_bytes(head, "little")))
        rows, arrays = meta["rows"], {}
        for c in meta["columns"]:
            sizes = c["sizes"]
            bufs = [pa.py_buffer(exact(sizes[0])) if sizes[0] else None]
            bufs += [pa.py_buffer(exact(n) if n else b"") for n in sizes[1:]]
            arrays[c["name"]] = pa.Array.from_buffers(types[c["type"]], rows, bufs, null_count=c["nulls"])
        table = pa.table(arrays)
        if writer is None:
            writer = pq.ParquetWriter(sink, table.schema, compression="zstd")
        writer.write_table(table, row_group_size=max(rows, 1))
        say("ok", sink.n)
    if writer is not None:
        writer.close()
    sink.flush()
    say("done", sink.n)
except EOFError:
    if writer is not None:
        writer.close()
    sink.flush()
except Exception as e:
    say("error", f"{type(e).__name__}: {e}")
    sys.exit(1)
)";

/// Validity bytes (one a row) as Arrow's bitmap (a bit a row, least significant first).
std::string bitmap(const std::vector<std::uint8_t>& valid) {
    std::string bits((valid.size() + 7) / 8, '\0');
    for (std::size_t i = 0; i < valid.size(); ++i) {
        if (valid[i]) bits[i / 8] = static_cast<char>(static_cast<unsigned char>(bits[i / 8]) | (1u << (i % 8)));
    }
    return bits;
}

void closeFd(int& fd) {
    if (fd >= 0) ::close(fd);
    fd = -1;
}

}  // namespace

void ParquetColumn::append(double v) {
    doubles_.push_back(v);
    valid_.push_back(1);
}

void ParquetColumn::append(std::int64_t v) {
    ints_.push_back(v);
    valid_.push_back(1);
}

void ParquetColumn::append(std::string_view v) {
    chars_.append(v);
    offsets_.push_back(static_cast<std::int32_t>(chars_.size()));
    valid_.push_back(1);
}

void ParquetColumn::appendNull() {
    switch (type_) {
        case Type::Float64:
            doubles_.push_back(0);
            break;
        case Type::Int64:
            ints_.push_back(0);
            break;
        case Type::String:
            offsets_.push_back(static_cast<std::int32_t>(chars_.size()));
            break;
    }
    valid_.push_back(0);
    ++nulls_;
}

void ParquetColumn::clear() {
    doubles_.clear();
    ints_.clear();
    offsets_.assign(1, 0);
    chars_.clear();
    valid_.clear();
    nulls_ = 0;
}

std::size_t ParquetColumn::bytes() const {
    return doubles_.size() * sizeof(double) + ints_.size() * sizeof(std::int64_t) +
           (type_ == Type::String ? offsets_.size() * sizeof(std::int32_t) + chars_.size() : 0) + valid_.size() / 8;
}

ParquetStream::ParquetStream(int fd) {
    std::string executable;
    {
        const py::gil_scoped_acquire gil;
        executable = py::module_::import("sys").attr("executable").cast<std::string>();
    }
    if (executable.empty()) throw Unavailable("cannot find the Python interpreter to run pyarrow");
    int in[2], out[2];
    if (::pipe2(in, O_CLOEXEC) != 0) throw Unavailable(std::string("cannot start pyarrow: ") + std::strerror(errno));
    if (::pipe2(out, O_CLOEXEC) != 0) {
        ::close(in[0]);
        ::close(in[1]);
        throw Unavailable(std::string("cannot start pyarrow: ") + std::strerror(errno));
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in[0], 0);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    posix_spawn_file_actions_adddup2(&actions, fd, 3);
    // A Python warning or a crash must not reach the run's stderr as a traceback: the answer says why.
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    // Its own process group, signals blocked: a Ctrl-C or a `timeout` reaches sbsim alone, which
    // then closes the file through the child.
    sigset_t blocked;
    sigemptyset(&blocked);
    sigaddset(&blocked, SIGINT);
    sigaddset(&blocked, SIGTERM);
    posix_spawnattr_setsigmask(&attr, &blocked);
    posix_spawnattr_setpgroup(&attr, 0);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK);
    std::vector<std::string> words{executable, "-c", kChild};
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    const int rc = ::posix_spawn(&child_, executable.c_str(), &actions, &attr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    ::close(in[0]);
    ::close(out[1]);
    toChild_ = in[1];
    fromChild_ = out[0];
    if (rc != 0) {
        child_ = -1;
        closeFd(toChild_);
        closeFd(fromChild_);
        throw Unavailable("cannot start " + executable + ": " + std::strerror(rc));
    }
    try {
        (void)answer(true);
    } catch (const WriteError& e) {
        throw Unavailable(e.what());
    }
}

ParquetStream::~ParquetStream() {
    closeFd(toChild_);
    closeFd(fromChild_);
    reap();
}

void ParquetStream::reap() {
    if (child_ < 0) return;
    int status = 0;
    while (::waitpid(child_, &status, 0) < 0 && errno == EINTR) {
    }
    child_ = -1;
}

void ParquetStream::send(const void* data, std::size_t size) {
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t n = ::write(toChild_, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            // The child ended: its last words say why.
            (void)answer(false);
            throw WriteError("the Parquet writer ended");
        }
        p += n;
        size -= static_cast<std::size_t>(n);
    }
}

std::string ParquetStream::answer(bool starting) {
    std::size_t eol;
    while ((eol = pending_.find('\n')) == std::string::npos) {
        char buffer[512];
        const ssize_t n = fromChild_ >= 0 ? ::read(fromChild_, buffer, sizeof buffer) : 0;
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            closeFd(toChild_);
            closeFd(fromChild_);
            reap();
            throw WriteError(starting ? "pyarrow's Parquet writer did not start" : "the Parquet writer ended");
        }
        pending_.append(buffer, static_cast<std::size_t>(n));
    }
    std::string line = pending_.substr(0, eol);
    pending_.erase(0, eol + 1);
    if (line.rfind("error ", 0) == 0) {
        closeFd(toChild_);
        closeFd(fromChild_);
        reap();
        const std::string why = line.substr(6);
        if (starting) throw WriteError("pyarrow cannot write Parquet (pip install pyarrow): " + why);
        throw WriteError(why);
    }
    return line;
}

std::uint64_t ParquetStream::writeRowGroup(const std::vector<ParquetColumn>& columns) {
    if (toChild_ < 0) throw WriteError("the Parquet writer ended");
    const std::size_t rows = columns.empty() ? 0 : columns.front().size();
    nlohmann::json header = {{"rows", rows}, {"columns", nlohmann::json::array()}};
    std::vector<std::string> bitmaps;
    bitmaps.reserve(columns.size());
    for (const ParquetColumn& c : columns) {
        if (c.size() != rows) throw std::logic_error("ParquetStream: columns of different lengths");
        bitmaps.push_back(c.nulls() > 0 ? bitmap(c.valid_) : std::string());
        nlohmann::json sizes = nlohmann::json::array({bitmaps.back().size()});
        const char* type = "str";
        switch (c.type()) {
            case ParquetColumn::Type::Float64:
                type = "f8";
                sizes.push_back(c.doubles_.size() * sizeof(double));
                break;
            case ParquetColumn::Type::Int64:
                type = "i8";
                sizes.push_back(c.ints_.size() * sizeof(std::int64_t));
                break;
            case ParquetColumn::Type::String:
                sizes.push_back(c.offsets_.size() * sizeof(std::int32_t));
                sizes.push_back(c.chars_.size());
                break;
        }
        header["columns"].push_back({{"name", c.name()}, {"type", type}, {"nulls", c.nulls()}, {"sizes", sizes}});
    }
    const std::string text = header.dump();
    // Little-endian, as the child reads it (and as the buffers are: x86-64, aarch64).
    std::uint64_t length = text.size();
    unsigned char prefix[8];
    for (unsigned char& b : prefix) {
        b = static_cast<unsigned char>(length & 0xff);
        length >>= 8;
    }
    send(prefix, sizeof prefix);
    send(text.data(), text.size());
    for (std::size_t k = 0; k < columns.size(); ++k) {
        const ParquetColumn& c = columns[k];
        send(bitmaps[k].data(), bitmaps[k].size());
        switch (c.type()) {
            case ParquetColumn::Type::Float64:
                send(c.doubles_.data(), c.doubles_.size() * sizeof(double));
                break;
            case ParquetColumn::Type::Int64:
                send(c.ints_.data(), c.ints_.size() * sizeof(std::int64_t));
                break;
            case ParquetColumn::Type::String:
                send(c.offsets_.data(), c.offsets_.size() * sizeof(std::int32_t));
                send(c.chars_.data(), c.chars_.size());
                break;
        }
    }
    const std::string reply = answer(false);
    if (reply.rfind("ok ", 0) != 0) throw WriteError("the Parquet writer answered '" + reply + "'");
    return std::stoull(reply.substr(3));
}

std::uint64_t ParquetStream::close() {
    if (toChild_ < 0) throw WriteError("the Parquet writer ended");
    closeFd(toChild_);  // end of input: the child writes the footer
    const std::string reply = answer(false);
    closeFd(fromChild_);
    reap();
    if (reply.rfind("done ", 0) != 0) throw WriteError("the Parquet writer answered '" + reply + "'");
    return std::stoull(reply.substr(5));
}

}  // namespace sbsim::python
