// The keys every lesson's window takes, one table: `--help` prints it (options.cpp), so the list
// a student reads is the list the window was written against. A lesson's own keys are its
// options' (Option::key). Keep it in step with onKey in window_ui.cpp.
#pragma once

namespace stencil {

struct WindowKey {
  const char* keys;  // as the student presses them: "shift+P", "PgDn"
  const char* what;
};

inline constexpr WindowKey kWindowKeys[] = {
    {"drag", "orbit the camera"},
    {"wheel", "zoom"},
    {"R", "reset the camera"},
    {"V", "next variant"},
    {"P, shift+P", "step forward, back through the passes"},
    {"Tab", "cycle the colour, stencil, grey (the stencil values stretched to grey, the largest white), bit-plane and depth views (shift: back)"},
    {"Space", "pause"},
    {"S, shift+S", "save a screenshot of the picture, of the whole window with the panel"},
    {"PgDn, PgUp", "next, previous lesson (in the course lessons/run opens)"},
    {"F1", "hide or show the panel"},
    {"+, -", "larger, smaller UI scale (text, widgets, stencil legend)"},
    {"F2", "print the frame rate and the lesson's time"},
    {"Esc", "quit (while a typed slider value is edited: end the edit)"},
};

}  // namespace stencil
