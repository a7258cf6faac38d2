# The web build: Flood for WebAssembly through Debian's emscripten (scripts/web.sh, docs/WEB.md).
# Included by the top CMakeLists.txt when CMake runs under emcmake. What Debian has only as
# source packages (scripts/web-deps.sh unpacks them into FLOOD_WEB_DEPS) is compiled here;
# header-only packages (nlohmann-json, CLI11, stb) are used as the native build uses them.
set(FLOOD_WEB_DEPS "${CMAKE_BINARY_DIR}/deps/src" CACHE PATH
    "Debian source packages for the web build (scripts/web-deps.sh)")
# Neither the test binary, Python, GDAL nor giflib run in a page; man pages need the native program.
set(FLOOD_TESTS OFF CACHE BOOL "Build the test suite")
set(FLOOD_PYTHON OFF CACHE BOOL "Build the Python module flood")
set(FLOOD_GDAL OFF CACHE BOOL "GIS formats through GDAL")
set(FLOOD_GIF OFF CACHE BOOL "Animated GIF exports")
set(HELP2MAN HELP2MAN-NOTFOUND CACHE FILEPATH "help2man")

function(flood_web_source var pattern)  # the unpacked source package matching `pattern`
  file(GLOB found LIST_DIRECTORIES true "${FLOOD_WEB_DEPS}/${pattern}")
  if(NOT found)
    message(FATAL_ERROR "web build: no ${FLOOD_WEB_DEPS}/${pattern}: run scripts/web-deps.sh")
  endif()
  list(GET found 0 dir)
  set(${var} ${dir} PARENT_SCOPE)
endfunction()
flood_web_source(IMGUI_SRC imgui-*)
flood_web_source(SIMDJSON_SRC simdjson-*)
flood_web_source(DCONV_SRC double-conversion-*)
flood_web_source(GMP_SRC gmp-*)

# Header-only Debian packages by their folder, never /usr/include itself (the host's libc).
set(FLOOD_WEB_HEADERS ${CMAKE_BINARY_DIR}/web-include)
foreach(dir nlohmann CLI)
  if(NOT EXISTS /usr/include/${dir})
    message(FATAL_ERROR "web build: no /usr/include/${dir}: run scripts/web-deps.sh")
  endif()
  file(MAKE_DIRECTORY ${FLOOD_WEB_HEADERS})
  file(CREATE_LINK /usr/include/${dir} ${FLOOD_WEB_HEADERS}/${dir} SYMBOLIC)
endforeach()

# Exceptions on, at compile and link: malformed input is an exception caught into a message
# and exit code 3; without them the program aborts. The core's to_chars/from_chars for double.
add_compile_options(-fexceptions "SHELL:-include ${CMAKE_SOURCE_DIR}/web/charconv_double.h")
add_link_options(-fexceptions -sALLOW_MEMORY_GROWTH=1)
include_directories(SYSTEM ${CMAKE_SOURCE_DIR}/web/include ${FLOOD_WEB_HEADERS} ${DCONV_SRC}
                    ${GMP_SRC}/mini-gmp /usr/include/stb)

# GMP (mini-gmp), double-conversion, std::thread run inline, and stb's PNG writer: one archive,
# linked through GMP_LIBRARY wherever the core is.
file(GLOB DCONV_SOURCES ${DCONV_SRC}/double-conversion/*.cc)
add_library(floodweb_deps STATIC ${DCONV_SOURCES} ${CMAKE_SOURCE_DIR}/web/mini_gmp.c
            ${CMAKE_SOURCE_DIR}/web/inline_threads.c ${CMAKE_SOURCE_DIR}/web/stb_image_write.c)
target_compile_options(floodweb_deps PRIVATE -w)
set(GMP_LIBRARY floodweb_deps CACHE STRING "GMP: mini-gmp in the web build" FORCE)

add_library(floodweb_simdjson STATIC ${SIMDJSON_SRC}/singleheader/simdjson.cpp)
target_include_directories(floodweb_simdjson SYSTEM PUBLIC ${SIMDJSON_SRC}/singleheader)
target_compile_options(floodweb_simdjson PRIVATE -w)

# Dear ImGui with its GLFW and OpenGL ES 3 (WebGL 2) backends; GLFW is Emscripten's own.
add_library(floodweb_imgui STATIC ${IMGUI_SRC}/imgui.cpp ${IMGUI_SRC}/imgui_draw.cpp
            ${IMGUI_SRC}/imgui_tables.cpp ${IMGUI_SRC}/imgui_widgets.cpp
            ${IMGUI_SRC}/backends/imgui_impl_glfw.cpp ${IMGUI_SRC}/backends/imgui_impl_opengl3.cpp)
target_include_directories(floodweb_imgui SYSTEM PUBLIC ${IMGUI_SRC})
target_compile_definitions(floodweb_imgui PUBLIC IMGUI_IMPL_OPENGL_ES3)
target_compile_options(floodweb_imgui PRIVATE -w)
target_link_options(floodweb_imgui INTERFACE -sUSE_GLFW=3 -sMIN_WEBGL_VERSION=2
                    -sMAX_WEBGL_VERSION=2)

# find_package() of the packages above finds these (CMake's package redirects).
function(flood_web_package name body)
  string(TOLOWER ${name} name)  # as CMake looks for it
  file(WRITE ${CMAKE_FIND_PACKAGE_REDIRECTS_DIR}/${name}-config.cmake "${body}\n")
  file(WRITE ${CMAKE_FIND_PACKAGE_REDIRECTS_DIR}/${name}-config-version.cmake
       "set(PACKAGE_VERSION \"${PACKAGE_FIND_VERSION}\")\nset(PACKAGE_VERSION_COMPATIBLE TRUE)\n")
endfunction()
flood_web_package(nlohmann_json "if(NOT TARGET nlohmann_json::nlohmann_json)
  add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED GLOBAL)
endif()")
flood_web_package(CLI11 "if(NOT TARGET CLI11::CLI11)
  add_library(CLI11::CLI11 INTERFACE IMPORTED GLOBAL)
endif()")
flood_web_package(simdjson "if(NOT TARGET simdjson::simdjson)
  add_library(simdjson::simdjson INTERFACE IMPORTED GLOBAL)
  set_target_properties(simdjson::simdjson PROPERTIES INTERFACE_LINK_LIBRARIES floodweb_simdjson)
endif()")
flood_web_package(Threads "if(NOT TARGET Threads::Threads)
  add_library(Threads::Threads INTERFACE IMPORTED GLOBAL)
  set_target_properties(Threads::Threads PROPERTIES INTERFACE_LINK_LIBRARIES floodweb_deps)
endif()")

# The CLI runs under Node with the real file system (scripts/web.sh --test compares its output
# with the native one's).
function(flood_web_cli target)
  target_link_options(${target} PRIVATE -sNODERAWFS=1 -sEXIT_RUNTIME=1)
endfunction()

# The viewer as a page: index.html (web/shell.html), its .js, .wasm and .data (polygons/ as
# /polygons). ASYNCIFY lets the viewer's own loop yield to the browser at each frame; only the
# functions that are on the stack when it yields are instrumented (web/asyncify-only.txt: main,
# the run loops, platform::pollEvents and waitEvents, which await the next frame), not every
# function that might reach an indirect call: that was 1.3 MB of the 3.8 MB .wasm
# (docs/BENCHMARKS.md). A new caller of pollEvents/waitEvents must be added there, or the page
# stops after its first frame (the page test's first checks).
function(flood_web_page target)
  set(site ${CMAKE_BINARY_DIR}/site)
  set_target_properties(${target} PROPERTIES OUTPUT_NAME index SUFFIX .html
                        RUNTIME_OUTPUT_DIRECTORY ${site})
  target_link_options(${target} PRIVATE -sASYNCIFY -sASYNCIFY_STACK_SIZE=65536
    -sASYNCIFY_ONLY=@${CMAKE_SOURCE_DIR}/web/asyncify-only.txt
    -sMINIFY_HTML=0 -sEXPORTED_RUNTIME_METHODS=ccall,FS,UTF8ToString -sINITIAL_MEMORY=67108864
    "SHELL:--shell-file ${CMAKE_SOURCE_DIR}/web/shell.html"
    "SHELL:--pre-js ${CMAKE_SOURCE_DIR}/web/pre.js"
    -lidbfs.js  # settings and recent files in IndexedDB (web/pre.js)
    "SHELL:--preload-file ${CMAKE_SOURCE_DIR}/polygons@/polygons")
  file(GLOB polygons CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/polygons/*)
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${CMAKE_SOURCE_DIR}/web/shell.html
               ${CMAKE_SOURCE_DIR}/web/pre.js ${CMAKE_SOURCE_DIR}/web/asyncify-only.txt ${polygons})
endfunction()

# The page's shrinker (viewer/shrink_worker.h): the flood CLI linked once more, for a Web
# Worker, as site/shrink-worker.js and .wasm. web/shrink_worker.js runs `flood shrink` in it on
# the bytes the page posts; a crash there ends the worker, not the page. Built with the page.
function(flood_web_shrink_worker page)
  add_executable(flood-shrink-worker ${CMAKE_SOURCE_DIR}/cli/flood.cpp)
  target_link_libraries(flood-shrink-worker PRIVATE floodcli)
  set_target_properties(flood-shrink-worker PROPERTIES OUTPUT_NAME shrink-worker SUFFIX .js
                        RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/site)
  target_link_options(flood-shrink-worker PRIVATE -sENVIRONMENT=worker -sINVOKE_RUN=0
    "SHELL:--pre-js ${CMAKE_SOURCE_DIR}/web/shrink_worker.js")
  set_property(TARGET flood-shrink-worker APPEND PROPERTY LINK_DEPENDS
               ${CMAKE_SOURCE_DIR}/web/shrink_worker.js)
  add_dependencies(${page} flood-shrink-worker)
endfunction()
