# The GUI tests, their sources here, their targets defined by viewer/CMakeLists.txt, which
# includes this file when FLOOD_VIEWER and FLOOD_TESTS are on: in the viewer's directory
# (CMAKE_CURRENT_SOURCE_DIR is viewer/) two of them compile panels with the shaders header
# generated there, and all of them work in its build directory, as before they moved here.
set(GUI_TESTS ${CMAKE_CURRENT_LIST_DIR})
find_package(GTest REQUIRED)
# The top level enables testing after adding the viewer's directory; add_test needs it now.
enable_testing()

# The viewer's saved settings (its theme) would follow a screenshot: the tests see none of the
# machine's, an empty config folder of their own.
set(GUI_CONFIG ${CMAKE_CURRENT_BINARY_DIR}/gui-test-config)

# A test that runs flood-viewer itself (a screenshot, read back pixel by pixel): Xvfb needed,
# skipped (77) without a display. Mesa's unloaded driver looks like a leak to ASan; leak checks
# stay on for the other tests.
function(flood_screenshot_test name)
  add_executable(${name} ${GUI_TESTS}/${name}.cpp)
  target_link_libraries(${name} PRIVATE floodviewmodel PkgConfig::IMGUI)
  target_compile_definitions(${name} PRIVATE FLOOD_VIEWER="$<TARGET_FILE:flood-viewer>"
    FLOOD_CLI="$<TARGET_FILE:flood>" FLOOD_SOURCE_DIR="${CMAKE_SOURCE_DIR}"
    FLOOD_WORK_DIR="${CMAKE_CURRENT_BINARY_DIR}")
  add_dependencies(${name} flood-viewer flood)
  add_test(NAME viewer/${name} COMMAND ${name})
  set_tests_properties(viewer/${name} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 120
    ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;XDG_CONFIG_HOME=${GUI_CONFIG}")
endfunction()

# A test that drives panels through a window-free ImGui context (no display needed): its
# source, then the viewer's sources it compiles (panels, with the generated shaders header).
function(flood_windowless_test name)
  add_executable(${name} ${GUI_TESTS}/${name}.cpp ${ARGN} panel_common.cpp panel_edit.cpp
                 renderer.cpp platform_glfw.cpp ${SHADER_HEADER})
  target_include_directories(${name} PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/generated)
  target_compile_definitions(${name} PRIVATE FLOOD_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
  target_link_libraries(${name} PRIVATE floodviewmodel floodglad glfw PkgConfig::IMGUI
                        GTest::gtest_main)
  add_test(NAME viewer/${name} COMMAND ${name})
endfunction()

# ---- real screenshots, checked pixel by pixel (screenshot_support.h) -------------------------
flood_screenshot_test(screenshot_test)             # the canvas, the error view, a 10^5 face
flood_screenshot_test(presenter_screenshot_test)   # presenter view, scale, keys, light theme
flood_screenshot_test(inspector_screenshot_test)   # inspector, invariant lane, Decision panel
flood_screenshot_test(findings_screenshot_test)    # findings panel, tiny hole, labels, --layer

# ---- --version: the version and exit 0, as `flood --version` (needs no display) ------------
add_test(NAME viewer/version COMMAND sh -c
  "out=$(\"$0\" --version) && echo \"$out\" | grep -Eqx 'flood-viewer [0-9]+[.][0-9]+([.][0-9]+)?'"
  $<TARGET_FILE:flood-viewer>)

# ---- the command line (viewer/args.cpp, CLI11): parsed in-process, no window -------------------
flood_windowless_test(args_test args.cpp)
target_link_libraries(args_test PRIVATE CLI11::CLI11)
target_compile_definitions(args_test PRIVATE FLOOD_VERSION="${PROJECT_VERSION}")

# ---- the exports: runs flood-viewer headless, reads what it wrote ------------------------
add_executable(export_test ${GUI_TESTS}/export_test.cpp)
target_link_libraries(export_test PRIVATE floodviewmodel PkgConfig::IMGUI GTest::gtest_main)
target_compile_definitions(export_test PRIVATE FLOOD_VIEWER="$<TARGET_FILE:flood-viewer>"
  FLOOD_WORK_DIR="${CMAKE_CURRENT_BINARY_DIR}")
add_dependencies(export_test flood-viewer)
add_test(NAME viewer/export_test COMMAND export_test)
set_tests_properties(viewer/export_test PROPERTIES TIMEOUT 300 ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;XDG_CONFIG_HOME=${GUI_CONFIG}")

# ---- the Fig. 9 tree in the Decision panel, its path lit ---------------------------------
flood_screenshot_test(tree_screenshot_test)

# ---- edit mode's mouse and keys, through a window-free ImGui context (no display needed) ----
flood_windowless_test(edit_input_test)

# ---- the panels' per-trace state, kept per Ui (window-free ImGui, no display needed) ----------
flood_windowless_test(ui_state_test panel_transcript.cpp panel_timeline.cpp)
# ---- the Open panel: a collection that fails whole lists its features -----------------------
flood_windowless_test(open_panel_test panel_open.cpp)

# ---- the picture shows what the sentence says: Fig. 7 step 23 in presenter view -------------
flood_screenshot_test(narration_screenshot_test)

# ---- the State machine panel: no state's name cut (window-free ImGui, no display needed) -----
flood_windowless_test(state_machine_test panel_state_machine.cpp)

# ---- the quiz: the choices before an answer, the verdict and the lit path after -------------
flood_screenshot_test(quiz_screenshot_test)

# ---- the quiz's keys: Q, 1-5 and R B S J F (window-free ImGui, no display needed) -----------
flood_windowless_test(quiz_keys_test panel_quiz.cpp panel_help.cpp panel_decision.cpp)

# ---- views that hold: Fit into the canvas's free part, after presenter on and off ------------
flood_screenshot_test(fit_test)

# ---- Save PNG: the canvas alone, named and placed; --screenshot follows the saved theme ------
flood_screenshot_test(save_png_screenshot_test)

# ---- a big open: the outline and the progress box with Cancel while it floods ---------------
flood_screenshot_test(open_progress_test)

# ---- a 10^5-vertex outline: its boundary decimated to the pixel grid draws what every edge does
flood_screenshot_test(outline_pixels_test)
