#include "pipeline/scene_input.h"

#include <cstdio>
#include <filesystem>

#include "core/density_view.h"
#include "core/error.h"
#include "core/file_kind.h"
#include "core/frame_pattern.h"
#include "core/vdb_sequence.h"
#include "render/light_transport_registry.h"

namespace eikon {
namespace {

void parseSize(const std::string& text, RenderSettings& render) {
    int w = 0, h = 0;
    char x = 0;
    if (std::sscanf(text.c_str(), "%d%c%d", &w, &x, &h) != 3 || x != 'x' || w < 1 || h < 1 ||
        w > 16384 || h > 16384)
        throw Error("--size", "expected WIDTHxHEIGHT (e.g. 640x480), got '" + text + "'");
    render.width = w;
    render.height = h;
}

bool isPattern(const std::string& input) {
    return hasHashRun(toHashPattern(std::filesystem::path(input).filename().string(), input));
}

// One VDB file given with --frames: the sequence it is a frame of, said in one line; a file
// that is not numbered has no other frames to render.
Scene sequenceOfFile(const std::string& input, bool hold, const DefaultSceneChoices& camera,
                     std::vector<std::string>& notes) {
    VdbSequence seq;
    try {
        seq = findVdbSequence(input);
    } catch (const Error&) {
        throw Error(input,
                    "one file, not a frame of a sequence (name_0001.vdb), so --frames has no "
                    "other frames to render; render it without --frames");
    }
    notes.push_back(input + " is a frame of " + seq.pattern() + " (frames " + seq.framesText() +
                    "): --frames renders frames of that sequence");
    std::string note;
    Scene scene = defaultSceneForVdbSequence(input, hold, camera, note);
    if (!note.empty()) notes.push_back(note);
    return scene;
}

// "surface" (a name) or "1" (an index, digits only); "" chooses nothing.
GridChoice gridChoiceOf(const std::string& text) {
    GridChoice choice;
    if (text.empty()) return choice;
    if (text.find_first_not_of("0123456789") == std::string::npos && text.size() <= 6)
        choice.index = std::stoi(text);
    else
        choice.name = text;
    return choice;
}

}  // namespace

SceneInput readSceneInput(const std::string& input, const InputChoices& choices) {
    SceneInput in;
    DefaultSceneChoices camera;
    if (!choices.up.empty()) {
        camera.up = parseUpAxis(choices.up);
        if (!camera.up) throw Error("--up", "expected x, y or z, got '" + choices.up + "'");
    }
    camera.grid = gridChoiceOf(choices.grid);
    const bool sequence = isPattern(input) || choices.framesGiven;
    if (camera.grid.given() && sequence)
        throw Error("--grid", "picks a level set in one VDB file; " + input +
                                  (choices.framesGiven ? " with --frames" : "") +
                                  " is a sequence, and level sets are read one file at a time");
    std::string note;
    if (isPattern(input)) {
        in.scene = defaultSceneForVdbSequence(input, choices.hold, camera, note);
    } else {
        switch (sniffFileKind(input)) {
            case FileKind::Json:
                if (camera.up)
                    throw Error("--up", "applies to a VDB input's automatic camera; " + input +
                                            " is a scene, whose camera is its own");
                if (camera.grid.given())
                    throw Error("--grid", "picks a level set in a VDB input; " + input +
                                              " is a scene (its meshes take \"grid\")");
                in.scene = loadScene(input);
                in.oneFrame = in.scene.time.frameStart == in.scene.time.frameEnd;
                break;
            case FileKind::Vdb:
            case FileKind::NanoVdb:  // read by the same importer (core/nanovdb_reader.h)
                if (choices.framesGiven) {
                    in.scene = sequenceOfFile(input, choices.hold, camera, in.notes);
                } else {
                    in.scene = defaultSceneForVdb(input, camera, note);
                    in.scene.output.name = std::filesystem::path(input).stem().string();
                    in.oneFrame = true;
                }
                break;
        }
    }
    if (!note.empty()) in.notes.push_back(note);
    if (choices.hold)
        for (SourceSpec& src : in.scene.sources)
            if (src.type == SourceType::VdbSequence) src.holdMissingFrames = true;
    // The light-transport section is read by the methods, in render: checked here, before any
    // work, like the rest of the scene.
    checkLightTransport(in.scene);
    if (!choices.size.empty()) parseSize(choices.size, in.scene.render);
    return in;
}

}  // namespace eikon
