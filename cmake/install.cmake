# `cmake --install BUILD --prefix PREFIX`: the binary, its data (presets, shaders) under
# share/particle-lab, a desktop entry and icons, a man page and bash completion. Every path is
# relative to the prefix, so the installed tree can be moved as a whole (src/app/data_dir.hpp).
include(GNUInstallDirs)
set(PL_DATA_DEST ${CMAKE_INSTALL_DATADIR}/particle-lab)

install(TARGETS particle-lab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY presets/ DESTINATION ${PL_DATA_DEST}/presets FILES_MATCHING PATTERN "*.json")
if(PL_GUI)
  install(DIRECTORY shaders/ DESTINATION ${PL_DATA_DEST}/shaders)
  install(FILES packaging/particle-lab.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
  install(FILES packaging/particle-lab.svg DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
endif()
install(FILES LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})

# Generated from the program itself at build time, so they always describe the options it has
# (skipped when cross-compiling: the binary cannot run on the build machine).
if(NOT CMAKE_CROSSCOMPILING)
  set(PL_COMPLETION ${CMAKE_CURRENT_BINARY_DIR}/particle-lab.bash-completion)
  add_custom_command(OUTPUT ${PL_COMPLETION}
    COMMAND particle-lab --bash-completion > ${PL_COMPLETION}
    DEPENDS particle-lab COMMENT "Generating bash completion")
  set(PL_GENERATED ${PL_COMPLETION})
  install(FILES ${PL_COMPLETION} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
          RENAME particle-lab)

  find_program(HELP2MAN help2man)
  if(HELP2MAN)
    set(PL_MAN ${CMAKE_CURRENT_BINARY_DIR}/particle-lab.1)
    add_custom_command(OUTPUT ${PL_MAN}
      COMMAND ${HELP2MAN} --no-info --section=1 --name "a lab for Newtonian particle experiments"
              --output ${PL_MAN} $<TARGET_FILE:particle-lab>
      DEPENDS particle-lab COMMENT "Generating the man page (help2man)")
    list(APPEND PL_GENERATED ${PL_MAN})
    install(FILES ${PL_MAN} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  else()
    message(STATUS "help2man not found: no man page (Debian package help2man)")
  endif()
  add_custom_target(pl_generated_docs ALL DEPENDS ${PL_GENERATED})
endif()
