# petersen_module(TARGET NAME): makes TARGET (a library of this folder, with its public headers in
# include/ and its private ones in src/) the installed, exported target petersen::NAME. A new
# module needs one call after its add_library().
function(petersen_module target name)
  add_library(petersen::${name} ALIAS ${target})
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    set(scope INTERFACE)
  else()
    set(scope PUBLIC)
    if(IS_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/src)
      target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
    endif()
  endif()
  target_include_directories(${target} ${scope}
                             $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
                             $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  if(PETERSEN_INSTALL)
    install(TARGETS ${target} EXPORT petersenTargets
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
            LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
            RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
  set_property(GLOBAL APPEND PROPERTY PETERSEN_MODULES ${name})
endfunction()
