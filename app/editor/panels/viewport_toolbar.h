#pragma once
// The viewport's toolbar, above the picture: render path, tone map, exposure, the Camera list and
// field of view, compare A/B and its view, and a model being read (with its Cancel).

namespace patina::editor {

struct Document;
struct Interaction;
struct Jobs;
struct Prompts;

// The toolbar's controls wrap onto a second line when the viewport is narrow.
void drawViewportToolbar(Document& document, Interaction& interaction, Jobs& jobs, Prompts& prompts);

}  // namespace patina::editor
