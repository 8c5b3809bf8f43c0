#pragma once
// What every fuzz target shares. The readers take a path, as the command line gives them one, so
// each input is written to a file in a folder of this process's own (under /dev/shm, in memory,
// where there is one) and read back through the reader's public entry point.
//
// The expected outcomes are a result or an eikon::Error whose message is one printable line.
// Anything else is a finding and aborts, so libFuzzer saves the input: another exception type
// escaping, an error message or warning with a control character in it (it would break the
// one-line promise of core/error.h) or a report line with one, a crash or a sanitizer report, and,
// through libFuzzer's own -timeout and -rss_limit_mb, a hang or a runaway allocation.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <streambuf>
#include <string>
#include <typeinfo>

#include "core/error.h"
#include "core/log.h"
#include "core/memory_limit.h"
#include "core/printable.h"

namespace eikon::fuzz {

[[noreturn]] inline void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
    std::abort();
}

inline void expectOneLine(const std::string& kind, const std::string& text) {
    if (hasControlCharacter(text)) finding(kind + " holds a control character: " + printable(text));
}

// A report of several lines (`eikon info`'s text): each line printable.
inline void expectPrintableLines(const std::string& kind, const std::string& text) {
    for (std::size_t start = 0; start < text.size();) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        expectOneLine(kind, text.substr(start, end - start));
        start = end + 1;
    }
}

// The file every input of this process is written to, `extension` included (readers choose by
// it). Removed with its folder when the process exits normally.
inline const std::string& inputPath(const char* extension) {
    static const std::string path = [extension] {
        namespace fs = std::filesystem;
        std::error_code ec;
        const fs::path base =
            fs::is_directory("/dev/shm", ec) ? fs::path("/dev/shm") : fs::temp_directory_path();
        const fs::path dir = base / ("eikon-fuzz-" + std::to_string(::getpid()));
        fs::create_directories(dir);
        static const fs::path removeAtExit = dir;
        std::atexit([] {
            std::error_code ignored;
            fs::remove_all(removeAtExit, ignored);
        });
        return (dir / (std::string("input") + extension)).string();
    }();
    return path;
}

inline void writeInput(const std::string& path, const std::uint8_t* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    if (!out) finding("cannot write the input file " + path);
}

// A stream buffer that drops what it is given.
class DiscardBuffer : public std::streambuf {
protected:
    int overflow(int c) override { return traits_type::not_eof(c); }
    std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

// Library chatter (OpenVDB, OpenMesh, our own warnings) would drown libFuzzer's report, over
// millions of inputs: the C++ streams drop it, and warnings are only checked. libFuzzer and the
// sanitizers write to the file descriptor, which stays open.
inline void quietLibraries() {
    static DiscardBuffer discard;
    std::cerr.rdbuf(&discard);
    std::clog.rdbuf(&discard);
    std::cout.rdbuf(&discard);
    setLogSink([](LogLevel, const std::string& message) { expectOneLine("a warning", message); });
}

// eikon's memory limit (core/memory_limit.h) set under libFuzzer's -rss_limit_mb=2048
// (scripts/fuzz.sh): an input whose estimate is over it gets eikon's one-line refusal, as it would
// on a machine of that size, and one the estimate lets through but that takes more than 2 GB is a
// finding (the estimate was wrong).
inline void limitMemory() {
    setMemoryLimit(1024.0 * 1024.0 * 1024.0, "the fuzz targets' limit");
}

// What every target's LLVMFuzzerInitialize does first.
inline void setUpProcess() {
    quietLibraries();
    limitMemory();
}

// Runs one reader call; see the top of this file for what counts as a finding.
template <class ReadFn>
void readExpectingErrors(ReadFn read) {
    try {
        read();
    } catch (const Error& e) {
        expectOneLine("an eikon::Error", e.what());
    } catch (const std::exception& e) {
        finding(std::string("an exception of type ") + typeid(e).name() +
                " escaped: " + printable(e.what(), 200));
    } catch (...) {
        finding("an exception of unknown type escaped");
    }
}

}  // namespace eikon::fuzz
