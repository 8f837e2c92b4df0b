#!/usr/bin/env bash
# Installs the hairstyle_io Blender add-on (blender/hairstyle_io) into the user's Blender
# add-ons folder and enables it in the user preferences, so that File > Import offers
# "hairstyle strands (.h5)". Needs blender and, for the files, python3-h5py (Debian).
#
#   bash scripts/install-blender-addon.sh [BLENDER]     (default: blender on the PATH)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
blender=${1:-blender}
command -v "$blender" > /dev/null || { echo "install-blender-addon: no $blender (apt install blender python3-h5py)" >&2; exit 2; }
"$blender" -b --factory-startup --python-exit-code 1 --python-expr "
import addon_utils, bpy, os, shutil
folder = bpy.utils.user_resource('SCRIPTS', path='addons', create=True)
target = os.path.join(folder, 'hairstyle_io')
shutil.rmtree(target, ignore_errors=True)
shutil.copytree(os.path.join('$PWD', 'blender', 'hairstyle_io'), target,
                ignore=shutil.ignore_patterns('__pycache__'))
bpy.utils.refresh_script_paths()
addon_utils.modules_refresh()
bpy.ops.preferences.addon_enable(module='hairstyle_io')
bpy.ops.wm.save_userpref()
print('install-blender-addon: hairstyle_io installed in', target, 'and enabled')
" 2>&1 | grep -E "install-blender-addon|Error" || true
