// Key presses collected from GLFW between frames. A press and its release can both arrive
// within one frame (e.g. xdotool), so keys are queued from the callback rather than polled.
#pragma once

#include <bitset>
#include <vector>

struct GLFWwindow;

namespace pl::app {

struct KeyPress {
    int key = 0;   // GLFW_KEY_*
    int mods = 0;  // GLFW_MOD_*
};

struct InputQueue {
    std::vector<KeyPress> keys;
    // Keys pressed together with Ctrl, Alt or Super, until released: a shortcut (Ctrl+Q), never
    // a held camera key, even if the modifier is let go first.
    std::bitset<512> chorded;
};

// Install before ImGui's GLFW backend so it chains to this callback.
void install_key_queue(GLFWwindow* window, InputQueue* queue);

}  // namespace pl::app
