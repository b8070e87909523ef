#include "app/input_events.hpp"

#include <GLFW/glfw3.h>

namespace pl::app {

namespace {

void on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
    if (action == GLFW_RELEASE) return;
    auto* queue = static_cast<InputQueue*>(glfwGetWindowUserPointer(window));
    if (queue) queue->keys.push_back({key, mods});
}

}  // namespace

void install_key_queue(GLFWwindow* window, InputQueue* queue) {
    glfwSetWindowUserPointer(window, queue);
    glfwSetKeyCallback(window, on_key);
}

}  // namespace pl::app
