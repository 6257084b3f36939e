# ctest SceneSchema.EachKeyIsSpelledInOneFile (cmake -P, at test time): every
# key of the scene tables (src/scene/scene_tables.cpp: a row's `.name = "key"`
# or a key constant's `kName = "key"`) is spelled as "key" in exactly one file
# under src/ and python/src/ (issue 51: a key is declared once, as a row;
# other code refers to the row). Run with -DROOT=<source folder>.
#
# Exceptions: the same word meaning something else, or a key of a section
# whose table is still to come (path, surface, plate keys: path_kinds.cpp,
# geometry/surface_kinds.cpp). Each is "key|file|why".
set(exceptions
  "crf|src/media/mp4_writer.cpp|an encoder option of libav"
  "crf|src/media/webm_writer.cpp|an encoder option of libav"
  "crf|src/media/video_writer.hpp|a comment naming libav options"
  "preset|src/media/mp4_writer.cpp|an encoder option of libav"
  "preset|src/media/video_writer.hpp|a comment naming libav options"
  "loop|src/media/gif_writer.cpp|a muxer option of libav"
  "loop|src/media/video_writer.hpp|a comment naming libav options"
  "transparent|src/media/gif_writer.cpp|a comment on the GIF palette"
  "title|src/media/output_metadata.cpp|a metadata tag"
  "title|src/jobs/remembered_output.cpp|a metadata tag"
  "title|src/jobs/viewer_job.cpp|an HTML template field"
  "device|src/render/egl_context.cpp|an EGL platform name"
  "device|src/render/gl_context.hpp|an EGL platform name"
  "samples|src/render/frame_targets.cpp|a GL resolver option"
  "facts|src/motion/scene_facts.cpp|a stage name (StageLog)"
  "facts|src/motion/scene_facts.hpp|a stage name (StageLog)"
  "strobe|src/motion/frame_sampling.cpp|a stage name (StageLog)"
  "strobe|src/motion/frame_poses.cpp|a stage name (StageLog)"
  "trails|src/motion/frame_sampling.cpp|a stage name (StageLog)"
  "trails|src/motion/frame_poses.cpp|a stage name (StageLog)"
  "font|src/render/gpu_caches.cpp|a stage name (StageLog)"
  "width|python/src/rollspin_module.cpp|a Python keyword argument and property"
  "height|python/src/rollspin_module.cpp|a Python keyword argument and property"
  "transparent|python/src/rollspin_module.cpp|a Python keyword argument and property"
  "azimuth_deg|python/src/rollspin_module.cpp|a Python keyword argument"
  "length|src/core/param_table.hpp|a unit (a declaration's units)"
  "length|src/geometry/surface_kinds.cpp|a unit (a declaration's units)"
  "length|python/src/rollspin_module.cpp|a Python property (the path's length L)"
  "turns|src/scene/scene_spec.hpp|a fact's name (labels.facts)"
  "points|src/scene/path_kinds.cpp|a path kind's name"
  "points|src/scene/schema_reader.cpp|a unit (the typo hint for _pt)"
  "closed|src/geometry/uv_curve.cpp|a word of a curve's description"
  "v|src/scene/scene_overrides.cpp|the temporary key --set values are parsed under"
  "radius|src/geometry/surface_kinds.cpp|a surface kind's parameter"
  "radius|src/motion/scene_facts.cpp|a surface kind's parameter"
  "radius|src/scene/scene_spec.cpp|a surface kind's parameter"
  "height|src/geometry/surface_kinds.cpp|a surface kind's name"
  "height|src/scene/surface_kinds.hpp|a surface kind's name"
  "path|*|also a section's name (no table yet)"
  "surface|*|also a section's name (no table yet)"
)

file(READ "${ROOT}/src/scene/scene_tables.cpp" tables)
string(REGEX MATCHALL "(\\.name = |k[A-Za-z]+ = )\"[a-z_]+\"" spellings "${tables}")
set(keys "")
foreach(spelling IN LISTS spellings)
  string(REGEX REPLACE ".*\"([a-z_]+)\"" "\\1" name "${spelling}")
  list(APPEND keys "${name}")
endforeach()
list(REMOVE_DUPLICATES keys)
list(LENGTH keys key_count)
if(key_count LESS 40)
  message(FATAL_ERROR "found only ${key_count} keys in src/scene/scene_tables.cpp; has its row syntax changed?")
endif()

file(GLOB_RECURSE sources RELATIVE "${ROOT}" "${ROOT}/src/*.cpp" "${ROOT}/src/*.hpp" "${ROOT}/src/*.h"
     "${ROOT}/src/*.def" "${ROOT}/python/src/*.cpp" "${ROOT}/python/src/*.hpp")
foreach(name IN LISTS keys)
  set(files_${name} "")
endforeach()
foreach(file IN LISTS sources)
  file(READ "${ROOT}/${file}" text)
  foreach(name IN LISTS keys)
    string(FIND "${text}" "\"${name}\"" at)
    if(NOT at EQUAL -1)
      list(APPEND files_${name} "${file}")
    endif()
  endforeach()
endforeach()

set(problems "")
foreach(name IN LISTS keys)
  if("${exceptions}" MATCHES "(^|;)${name}\\|\\*\\|")
    continue()  # a word used everywhere for another meaning: not counted yet
  endif()
  set(counted "")
  foreach(file IN LISTS files_${name})
    set(excepted FALSE)
    foreach(entry IN LISTS exceptions)
      if(entry MATCHES "^${name}\\|${file}\\|")
        set(excepted TRUE)
      endif()
    endforeach()
    if(NOT excepted)
      list(APPEND counted "${file}")
    endif()
  endforeach()
  list(LENGTH counted n)
  if(NOT n EQUAL 1)
    list(JOIN counted ", " where)
    list(APPEND problems "\"${name}\" in ${n} files: ${where}")
  endif()
endforeach()
if(problems)
  list(JOIN problems "\n  " text)
  message(FATAL_ERROR "a scene key's quoted name belongs in src/scene/scene_tables.cpp only (refer to its row "
                      "or constant elsewhere):\n  ${text}")
endif()
message(STATUS "${key_count} scene keys, each spelled in one file")
