#include "app/input_events.hpp"

#include <GLFW/glfw3.h>

namespace pl::app {

namespace {

void on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
    auto* queue = static_cast<InputQueue*>(glfwGetWindowUserPointer(window));
    if (!queue) return;
    const bool tracked = key >= 0 && static_cast<std::size_t>(key) < queue->chorded.size();
    if (action == GLFW_RELEASE) {
        if (tracked) queue->chorded.reset(static_cast<std::size_t>(key));
        return;
    }
    if (action == GLFW_PRESS && tracked)
        queue->chorded.set(static_cast<std::size_t>(key), (mods & (GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER)) != 0);
    queue->keys.push_back({key, mods});
}

}  // namespace

void install_key_queue(GLFWwindow* window, InputQueue* queue) {
    glfwSetWindowUserPointer(window, queue);
    glfwSetKeyCallback(window, on_key);
}

}  // namespace pl::app
