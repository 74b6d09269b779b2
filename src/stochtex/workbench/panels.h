#pragma once
// The workbench's panels (issue 31 item 1), drawn with Dear ImGui from the
// model: the editing panel at the left (the document's source, the error
// and notice lines, the View and Analysis sections, the pattern's editors,
// undo, redo and saving) and the keys' help window. Every control's change
// is a WorkbenchCommand applied to the model (the editors' edits go through
// its gesture), so the panels hold only ImGui's own state.
#include "stochtex/workbench/editors.h"
#include "stochtex/workbench/model.h"
#include "stochtex/workbench/picture.h"

namespace stochtex {

class WorkbenchPanels {
public:
    // pixelScale: framebuffer pixels per window coordinate (ImGui lays out
    // in window coordinates); windowHeight and the texture's rectangle in
    // framebuffer pixels (the zoom slider zooms about its centre).
    void draw(WorkbenchModel& model, const WorkbenchPicture& picture, float pixelScale, int windowHeight,
              const DisplayRect& texture);

private:
    void drawViewControls(WorkbenchModel& model, const WorkbenchPicture& picture, const DisplayRect& texture);
    void drawAnalysis(WorkbenchModel& model, const WorkbenchPicture& picture);
    void drawEditors(WorkbenchModel& model, const WorkbenchPicture& picture);
    void drawHelp(WorkbenchModel& model);
    EditorState editorState_;
    bool expandAll_ = false;
    char saveAs_[256] = "edited.json";
};

}  // namespace stochtex
