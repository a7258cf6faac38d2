// A Dear ImGui context with no window and no GL, for the tests that drive panels frame by
// frame (edit_input_test.cpp, ui_state_test.cpp): a display size, a frame time and the font
// atlas NewFrame needs. ImGui::DestroyContext() ends it.
#pragma once
#include <imgui.h>

inline ImGuiIO& createWindowlessImGui(float width, float height) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(width, height);
    io.DeltaTime = 1.f / 60;
    unsigned char* pixels;
    int w, h;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    return io;
}
