// ShpackEditorScene.cs - how the editor scripts change a scene: each change recorded with
// Undo (one undo step per menu command) and the scene marked dirty, so that it is saved.
using System;
using System.Reflection;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace Shpack.Editor
{
    public static class ShpackEditorScene
    {
        // Shown before each command, and logged: Unity's own lighting bake (Generate Lighting,
        // or Auto Generate) recomputes the ambient probe from the skybox and rewrites the
        // baked probes, replacing what shpack set.
        public const string BakeWarning =
            "Unity's own lighting bake (Generate Lighting, or Auto Generate) overwrites the ambient probe " +
            "and the baked light probes that shpack sets. Apply shpack's values after baking, or turn Auto Generate off.";

        // Runs `change` as one undo step named `name`, then marks the active scene dirty.
        public static string Edit(string name, Func<string> change)
        {
            Undo.SetCurrentGroupName(name);
            int group = Undo.GetCurrentGroup();
            string done = change();
            Undo.CollapseUndoOperations(group);
            EditorSceneManager.MarkSceneDirty(SceneManager.GetActiveScene());
            return done;
        }

        // RenderSettings' values are fields of a hidden per-scene object, which Undo needs;
        // Unity exposes it only internally (RenderSettings.GetRenderSettings), so it is reached
        // by reflection. Where a Unity version lacks it, the change is made without undo.
        public static void RecordRenderSettings(string name)
        {
            MethodInfo get = typeof(RenderSettings).GetMethod("GetRenderSettings", BindingFlags.Static | BindingFlags.NonPublic);
            var settings = get == null ? null : get.Invoke(null, null) as UnityEngine.Object;
            if (settings != null) Undo.RecordObject(settings, name);
            else Debug.LogWarning("shpack: RenderSettings cannot be recorded for undo in this Unity version");
        }
    }
}
