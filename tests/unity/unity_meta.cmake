# unity_meta.cmake - the .meta files of the Unity package (unity/): written, or checked.
#
#   cmake -DPACKAGE_DIR=unity -DMODE=write -P tests/unity/unity_meta.cmake   after adding a file
#   cmake -DPACKAGE_DIR=unity -DMODE=check -P tests/unity/unity_meta.cmake   ctest unity_package_meta
#
# Unity ignores an asset of a package without a .meta (a git-URL install is read-only, so it
# cannot make one), and a .meta's GUID is how scenes and assets refer to the asset, so it
# must never change. Here the GUID is the MD5 of "com.shpack.lighting/" and the asset's path
# in the package: the same on every machine and for every run, different for every path.
# The importer section follows the file's kind; the native libraries staged by
# cmake/unity_plugin.cmake get their platform's plugin import settings, and their .meta is
# committed even while the binary (ignored by git) is absent.
#
# check fails unless every file and folder (names starting with "." are hidden from Unity)
# has the .meta this script writes, every .meta has its asset or is a staged library's, and
# the GUIDs are unique.
cmake_minimum_required(VERSION 3.20)
foreach(var PACKAGE_DIR MODE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "unity_meta.cmake: -D${var}=... is required")
  endif()
endforeach()
get_filename_component(PACKAGE_DIR ${PACKAGE_DIR} ABSOLUTE)

set(staged_plugins Plugins/Linux/x86_64/libshpack_c.so Plugins/Windows/x86_64/shpack_c.dll
                   Plugins/macOS/libshpack_c.dylib)

# The tail every importer section ends with.
set(tail "  userData:\n  assetBundleName:\n  assetBundleVariant:\n")

function(platform_entry out first enabled settings)
  set(${out} "  - first:\n      ${first}\n    second:\n      enabled: ${enabled}\n      settings:${settings}\n" PARENT_SCOPE)
endfunction()

# PluginImporter: loaded by the Editor on `editor_os` and included in the `standalone` player
# only; every other platform disabled.
function(plugin_importer out editor_os cpu standalone)
  platform_entry(any "Any:" 0 " {}")
  platform_entry(editor "Editor: Editor" 1 "\n        CPU: ${cpu}\n        DefaultValueInitialized: true\n        OS: ${editor_os}")
  set(players "")
  foreach(player Linux64 OSXUniversal Win64)
    if(player STREQUAL standalone)
      platform_entry(entry "Standalone: ${player}" 1 "\n        CPU: ${cpu}")
    else()
      platform_entry(entry "Standalone: ${player}" 0 "\n        CPU: None")
    endif()
    string(APPEND players "${entry}")
  endforeach()
  set(${out} "PluginImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  iconMap: {}\n  executionOrder: {}\n  defineConstraints: []\n  isPreloaded: 0\n  isOverridable: 0\n  isExplicitlyReferenced: 0\n  validateReferences: 1\n  platformData:\n${any}${editor}${players}${tail}" PARENT_SCOPE)
endfunction()

# The importer section of the asset at `path` (relative to the package).
function(importer out path is_folder)
  get_filename_component(name ${path} NAME)
  if(is_folder)
    set(text "folderAsset: yes\nDefaultImporter:\n  externalObjects: {}\n${tail}")
  elseif(path STREQUAL "Plugins/Linux/x86_64/libshpack_c.so")
    plugin_importer(text Linux x86_64 Linux64)
  elseif(path STREQUAL "Plugins/Windows/x86_64/shpack_c.dll")
    plugin_importer(text Windows x86_64 Win64)
  elseif(path STREQUAL "Plugins/macOS/libshpack_c.dylib")
    plugin_importer(text OSX AnyCPU OSXUniversal)
  elseif(name MATCHES "\\.cs$")
    set(text "MonoImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  defaultReferences: []\n  executionOrder: 0\n  icon: {instanceID: 0}\n${tail}")
  elseif(name MATCHES "\\.asmdef$")
    set(text "AssemblyDefinitionImporter:\n  externalObjects: {}\n${tail}")
  elseif(path STREQUAL "package.json")
    set(text "PackageManifestImporter:\n  externalObjects: {}\n${tail}")
  elseif(name MATCHES "\\.(md|txt|json)$")
    set(text "TextScriptImporter:\n  externalObjects: {}\n${tail}")
  else()
    set(text "DefaultImporter:\n  externalObjects: {}\n${tail}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

function(meta_text out path is_folder)
  string(MD5 guid "com.shpack.lighting/${path}")
  importer(section ${path} ${is_folder})
  set(${out} "fileFormatVersion: 2\nguid: ${guid}\n${section}" PARENT_SCOPE)
endfunction()

# The staged libraries' folders hold their committed .meta files.
if(MODE STREQUAL "write")
  foreach(plugin IN LISTS staged_plugins)
    get_filename_component(folder ${PACKAGE_DIR}/${plugin} DIRECTORY)
    file(MAKE_DIRECTORY ${folder})
  endforeach()
endif()

# Every asset Unity sees: files and folders, none hidden, no .meta; and the staged libraries.
file(GLOB_RECURSE entries LIST_DIRECTORIES true RELATIVE ${PACKAGE_DIR} ${PACKAGE_DIR}/*)
set(assets ${staged_plugins})
set(metas "")
foreach(entry IN LISTS entries)
  if(entry MATCHES "(^|/)\\.")
    continue()
  elseif(entry MATCHES "\\.meta$")
    list(APPEND metas ${entry})
  else()
    list(APPEND assets ${entry})
  endif()
endforeach()
list(REMOVE_DUPLICATES assets)
list(SORT assets)

set(problems "")
set(guids "")
foreach(asset IN LISTS assets)
  set(is_folder OFF)
  if(IS_DIRECTORY ${PACKAGE_DIR}/${asset})
    set(is_folder ON)
  endif()
  meta_text(want ${asset} ${is_folder})
  string(MD5 guid "com.shpack.lighting/${asset}")
  list(APPEND guids ${guid})
  set(meta ${PACKAGE_DIR}/${asset}.meta)
  if(MODE STREQUAL "write")
    file(WRITE ${meta} "${want}")
  elseif(NOT EXISTS ${meta})
    string(APPEND problems "  ${asset}: no .meta\n")
  else()
    file(READ ${meta} have)
    if(NOT have STREQUAL want)
      string(APPEND problems "  ${asset}.meta: not what unity_meta.cmake writes (MODE=write rewrites it)\n")
    endif()
  endif()
endforeach()

foreach(meta IN LISTS metas)
  string(REGEX REPLACE "\\.meta$" "" asset ${meta})
  if(NOT asset IN_LIST assets)
    string(APPEND problems "  ${meta}: its asset does not exist\n")
  endif()
endforeach()

set(unique ${guids})
list(REMOVE_DUPLICATES unique)
list(LENGTH guids count)
list(LENGTH unique unique_count)
if(NOT count EQUAL unique_count)
  string(APPEND problems "  two assets share a GUID\n")
endif()

if(MODE STREQUAL "check")
  if(problems)
    message(FATAL_ERROR "unity_meta.cmake: ${PACKAGE_DIR}:\n${problems}")
  endif()
  message("unity_meta.cmake: ${count} assets, each with its .meta and a unique GUID")
endif()
