#include "apps/regress_report.h"

#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_write.h"
#include "core/error.h"
#include "render/image.h"
#include "render/image_metrics.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

// Text for HTML and XML: the five special characters escaped, control characters (but tab and
// newline) dropped, as XML 1.0 does not allow them.
std::string escaped(const std::string& s) {
    std::string out;
    for (char ch : s) {
        const unsigned char c = static_cast<unsigned char>(ch);
        if (c < 0x20 && c != '\n' && c != '\t') continue;
        switch (ch) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            default:
                out += ch;
        }
    }
    return out;
}

std::string logTail(const std::string& path, size_t lines) {
    std::ifstream in(path);
    std::deque<std::string> last;
    std::string line;
    while (std::getline(in, line)) {
        last.push_back(line.size() > 400 ? line.substr(0, 400) + "…" : line);
        if (last.size() > lines) last.pop_front();
    }
    std::string out;
    for (const std::string& l : last) out += l + "\n";
    return out;
}

void writeText(const std::string& path, const std::string& text) {
    writeAtomically(path, [&](const std::string& partial) {
        std::ofstream out(partial, std::ios::binary);
        out << text;
        out.close();
        if (!out) throw Error(path, "could not write");
    });
}

// The picture of an image file for a browser: a PNG as it is, a linear EXR through the tone map.
void writeViewable(const std::string& source, bool linear, const std::string& destination) {
    if (!linear) {
        fs::copy_file(source, destination, fs::copy_options::overwrite_existing);
        return;
    }
    writePng(destination, readExr(source), 0.0f, ToneCurve::Filmic);
}

std::string imagesOf(const Finding& f, const std::string& dir, int index) {
    if (f.newImage.empty()) return "";
    std::ostringstream html;
    const std::string stem = "images/" + std::to_string(index);
    html << "<div class=\"row\">";
    try {
        writeViewable(f.newImage, f.linear, dir + "/" + stem + "_new.png");
        if (!f.referenceImage.empty()) {
            writeViewable(f.referenceImage, f.linear, dir + "/" + stem + "_reference.png");
            html << "<figure><img src=\"" << stem << "_reference.png\"><figcaption>reference"
                 << "</figcaption></figure>";
        }
        html << "<figure><img src=\"" << stem << "_new.png\"><figcaption>new</figcaption></figure>";
        if (!f.referenceImage.empty()) {
            const Image test = f.linear ? readExr(f.newImage) : readPng(f.newImage);
            const Image reference =
                f.linear ? readExr(f.referenceImage) : readPng(f.referenceImage);
            if (test.width == reference.width && test.height == reference.height) {
                double largest = 0.0;
                writePngRgb8(dir + "/" + stem + "_difference.png", test.width, test.height,
                             differenceHeatMap(test, reference, largest));
                char caption[96];
                std::snprintf(caption, sizeof caption, "difference (black 0, white %.4g)", largest);
                html << "<figure><img src=\"" << stem << "_difference.png\"><figcaption>"
                     << escaped(caption) << "</figcaption></figure>";
            }
        }
    } catch (const std::exception& e) {
        html << "<p>cannot show the images: " << escaped(e.what()) << "</p>";
    }
    html << "</div>\n";
    return html.str();
}

std::string gridsOf(const Finding& f) {
    std::ostringstream html;
    for (const GridDifference& g : f.grids) {
        html << "<p>grid <b>" << escaped(g.name) << "</b> (" << escaped(g.type)
             << "): " << g.voxelsOver << " of " << g.voxelsCompared
             << " voxels over the tolerance, largest " << g.maxDifference
             << "</p>\n<table><tr><th>voxel (i, j, k)</th><th>reference</th>"
             << "<th>new</th><th>difference</th></tr>\n";
        for (const VoxelDifference& v : g.worst)
            html << "<tr><td>" << v.ijk.x << ", " << v.ijk.y << ", " << v.ijk.z << "</td><td>"
                 << v.reference << "</td><td>" << v.test << "</td><td>" << v.difference
                 << "</td></tr>\n";
        html << "</table>\n";
    }
    return html.str();
}

}  // namespace

const char* statusWord(CaseStatus s) {
    switch (s) {
        case CaseStatus::Pass:
            return "pass";
        case CaseStatus::Fail:
            return "FAIL";
        case CaseStatus::Error:
            return "ERROR";
        case CaseStatus::Updated:
            return "updated";
    }
    return "?";
}

void writeHtmlReport(const std::string& dir, const std::string& suite,
                     const std::vector<CaseResult>& results, double seconds) {
    std::error_code ec;
    fs::create_directories(dir + "/images", ec);
    if (ec) throw Error(dir, "cannot create the report folder: " + ec.message());
    int passed = 0;
    for (const CaseResult& r : results) passed += r.status == CaseStatus::Pass;
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>eikon regress "
         << escaped(suite) << "</title>\n<style>body{font-family:sans-serif;margin:2em}"
         << "img{image-rendering:pixelated;min-width:192px;border:1px solid #888}"
         << "figure{display:inline-block;margin:0 1em 1em 0}.row{display:flex;flex-wrap:wrap}"
         << "td,th{padding:2px 8px;text-align:right}pre{background:#f4f4f4;padding:.5em}"
         << ".FAIL,.ERROR{color:#b00}.pass{color:#070}</style></head><body>\n"
         << "<h1>eikon regress " << escaped(suite) << "</h1>\n<p>" << results.size() << " cases, "
         << passed << " passed, " << seconds << " s</p>\n<ul>\n";
    for (const CaseResult& r : results)
        html << "<li><a href=\"#" << escaped(r.name) << "\">" << escaped(r.name)
             << "</a> <span class=\"" << statusWord(r.status) << "\">" << statusWord(r.status)
             << "</span></li>\n";
    html << "</ul>\n";
    int image = 0;
    for (const CaseResult& r : results) {
        if (r.status == CaseStatus::Pass || r.status == CaseStatus::Updated) continue;
        html << "<h2 id=\"" << escaped(r.name) << "\">" << escaped(r.name) << " <span class=\""
             << statusWord(r.status) << "\">" << statusWord(r.status) << "</span></h2>\n";
        if (!r.description.empty()) html << "<p>" << escaped(r.description) << "</p>\n";
        if (r.status == CaseStatus::Error) {
            html << "<p>" << escaped(r.reason) << "</p>\n<pre>" << escaped(logTail(r.logPath, 20))
                 << "</pre>\n";
            continue;
        }
        for (const Finding& f : r.findings) {
            html << "<h3>" << escaped(f.key) << "</h3>\n<p>" << escaped(f.reason) << "</p>\n";
            html << imagesOf(f, dir, image++) << gridsOf(f);
        }
    }
    html << "</body></html>\n";
    writeText(dir + "/index.html", html.str());
}

void writeJUnit(const std::string& path, const std::string& suite,
                const std::vector<CaseResult>& results, double seconds) {
    int failures = 0, errors = 0;
    for (const CaseResult& r : results) {
        failures += r.status == CaseStatus::Fail;
        errors += r.status == CaseStatus::Error;
    }
    std::ostringstream xml;
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n  <testsuite name=\"eikon "
           "regress "
        << escaped(suite) << "\" tests=\"" << results.size() << "\" failures=\"" << failures
        << "\" errors=\"" << errors << "\" time=\"" << seconds << "\">\n";
    for (const CaseResult& r : results) {
        xml << "    <testcase classname=\"" << escaped(fs::path(suite).filename().string())
            << "\" name=\"" << escaped(r.name) << "\" time=\"" << r.seconds << "\"";
        if (r.status == CaseStatus::Pass || r.status == CaseStatus::Updated) {
            xml << "/>\n";
            continue;
        }
        const char* tag = r.status == CaseStatus::Fail ? "failure" : "error";
        std::string body;
        for (const Finding& f : r.findings) body += f.key + ": " + f.reason + "\n";
        if (r.status == CaseStatus::Error) body = logTail(r.logPath, 20);
        xml << ">\n      <" << tag << " message=\"" << escaped(r.reason) << "\">" << escaped(body)
            << "</" << tag << ">\n    </testcase>\n";
    }
    xml << "  </testsuite>\n</testsuites>\n";
    writeText(path, xml.str());
}

}  // namespace eikon::app
