# Install.TinyProgramRendersWithTheInstalledTree (docs/install.md):
#   cmake -DBUILD=build -DSOURCE=. -DWORK=scratch -DDERMIS=build/dermis
#         [-DLAUNCHER=ccache] -P tests/install/check_install.cmake
# 1. `cmake --install` the build into a staging prefix, then move the prefix
#    (an installed tree must not depend on where it was installed);
# 2. build tests/install/consumer, a program outside the tree, against it
#    with find_package(Dermis), and install it into the same prefix;
# 3. render one frame of the installed default scene with it, and with the
#    installed `dermis`: each must read the installed shaders (not the source
#    tree's, which also exist here) and write the same bytes as the build
#    tree's `dermis render` of the source tree's scene;
# 4. make the .deb with CPack, check its contents and dependencies, unpack it
#    (no root needed) and render the same frame with its `dermis`.

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${what} failed (${result}):\n${out}\n${err}")
  endif()
  set(lastOutput "${out}" PARENT_SCOPE)
endfunction()

foreach(required BUILD SOURCE WORK DERMIS)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "check_install.cmake needs -D${required}=...")
  endif()
  get_filename_component(${required} ${${required}} ABSOLUTE)
endforeach()
file(REMOVE_RECURSE ${WORK})
set(prefix ${WORK}/moved/usr)
set(size 64x36)
# No environment override: the programs must find the installed data themselves.
set(clean ${CMAKE_COMMAND} -E env --unset=DERMIS_SHADER_DIR --unset=DERMIS_DATA_DIR)

run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD} --prefix ${WORK}/staged/usr)
file(RENAME ${WORK}/staged ${WORK}/moved)

set(launcher "")
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run("configuring the consumer" ${CMAKE_COMMAND} -S ${SOURCE}/tests/install/consumer -B ${WORK}/consumer -G Ninja
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_INSTALL_PREFIX=${prefix} ${launcher})
run("building the consumer" ${CMAKE_COMMAND} --build ${WORK}/consumer)
run("installing the consumer" ${CMAKE_COMMAND} --install ${WORK}/consumer)

set(scene ${prefix}/share/dermis/content/scenes/default.json)
run("render_one_frame" ${clean} ${prefix}/bin/render_one_frame ${scene} ${size} ${WORK}/consumer.png)
if(NOT lastOutput STREQUAL "shaders: ${prefix}/share/dermis/shaders\n")
  message(FATAL_ERROR "render_one_frame read the shaders elsewhere than the installed tree: ${lastOutput}")
endif()

# `dermis --version` names the folders it reads.
function(check_data_folders program root)
  run("${program} --version" ${clean} ${program} --version)
  foreach(kind shaders content tools)
    if(NOT lastOutput MATCHES "\n${kind}: *${root}/share/dermis/${kind}\n")
      message(FATAL_ERROR "${program} reads its ${kind} elsewhere than ${root}:\n${lastOutput}")
    endif()
  endforeach()
endfunction()
check_data_folders(${prefix}/bin/dermis ${prefix})
run("installed dermis render" ${clean} ${prefix}/bin/dermis render ${scene} --size ${size} --frames 1
    --out ${WORK}/installed.png --quiet)
run("build-tree dermis render" ${clean} ${DERMIS} render ${SOURCE}/content/scenes/default.json --size ${size}
    --frames 1 --out ${WORK}/build.png --quiet)

run("cpack" ${CMAKE_COMMAND} -E chdir ${WORK} cpack --config ${BUILD}/CPackConfig.cmake -B ${WORK}/package)
file(GLOB deb ${WORK}/package/dermis_*.deb)
run("dpkg-deb --contents" dpkg-deb --contents ${deb})
foreach(path usr/bin/dermis usr/share/dermis/shaders/lighting.frag usr/share/dermis/content/scenes/default.json
        usr/share/dermis/tools/plot_bench.py usr/include/dermis/frame/Renderer.h usr/lib/cmake/Dermis/DermisConfig.cmake)
  if(NOT lastOutput MATCHES " \\./${path}\n")
    message(FATAL_ERROR "${deb} lacks ${path}:\n${lastOutput}")
  endif()
endforeach()
run("dpkg-deb --field" dpkg-deb --field ${deb} Depends)
foreach(library libopenimageio libembree3 libosmesa6 libegl1)
  if(NOT lastOutput MATCHES "${library}")
    message(FATAL_ERROR "${deb} does not depend on ${library}: ${lastOutput}")
  endif()
endforeach()
run("dpkg-deb --extract" dpkg-deb --extract ${deb} ${WORK}/unpacked)
check_data_folders(${WORK}/unpacked/usr/bin/dermis ${WORK}/unpacked/usr)
run("the package's dermis render" ${clean} ${WORK}/unpacked/usr/bin/dermis render
    ${WORK}/unpacked/usr/share/dermis/content/scenes/default.json --size ${size} --frames 1 --out ${WORK}/package.png --quiet)

foreach(image consumer installed package)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/${image}.png ${WORK}/build.png
                  RESULT_VARIABLE different)
  if(different)
    message(FATAL_ERROR "${WORK}/${image}.png differs from the build tree's render ${WORK}/build.png")
  endif()
endforeach()
message(STATUS "the installed tree renders the build tree's image (${WORK})")
