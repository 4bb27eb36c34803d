/* SPDX-License-Identifier: MIT */
#include "viewer_input.h"

#include <GLFW/glfw3.h>

static viewer_input *of(GLFWwindow *w)
{
    return (viewer_input *)glfwGetWindowUserPointer(w);
}

static void on_key(GLFWwindow *w, int key, int scancode, int action, int mods)
{
    viewer_input *in = of(w);
    (void)scancode;
    (void)mods;
    if (action == GLFW_PRESS && in->key_count < VIEWER_INPUT_KEYS)
        in->keys[in->key_count++] = key;
}

static void on_button(GLFWwindow *w, int button, int action, int mods)
{
    viewer_input *in = of(w);
    (void)mods;
    if (button != GLFW_MOUSE_BUTTON_LEFT)
        return;
    in->dragging = action == GLFW_PRESS;
    glfwGetCursorPos(w, &in->last_x, &in->last_y);
}

static void on_move(GLFWwindow *w, double x, double y)
{
    viewer_input *in = of(w);
    if (in->dragging) {
        in->drag_x += x - in->last_x;
        in->drag_y += y - in->last_y;
    }
    in->last_x = x;
    in->last_y = y;
}

static void on_scroll(GLFWwindow *w, double dx, double dy)
{
    (void)dx;
    of(w)->wheel += dy;
}

void viewer_input_attach(viewer_input *in, viewer_window *w)
{
    in->dragging = 0;
    glfwSetWindowUserPointer(w->glfw, in);
    glfwSetKeyCallback(w->glfw, on_key);
    glfwSetMouseButtonCallback(w->glfw, on_button);
    glfwSetCursorPosCallback(w->glfw, on_move);
    glfwSetScrollCallback(w->glfw, on_scroll);
}

void viewer_input_poll(void)
{
    glfwPollEvents();
}

void viewer_input_clear(viewer_input *in)
{
    in->key_count = 0;
    in->drag_x = in->drag_y = in->wheel = 0;
}
