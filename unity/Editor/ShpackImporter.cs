// ShpackImporter.cs - the Editor menu *Tools > shpack*, each command one undo step that marks
// the scene dirty, each confirmed after the warning that Unity's own bake overwrites it:
//
//   Set Ambient Probe from JSON...               ShpackAmbient.FromDocument (and its lights)
//   Set Ambient Probe from Selected Map          ShpackAmbient.FromMap: a Cubemap or Texture2D
//   Set Ambient Probe and Sun from Selected Map  the same, an equirect map's sun as a light
//   Set Baked Light Probes from JSON...          ShpackBakedProbes.FromDocument, saved as an asset
using System;
using UnityEditor;
using UnityEngine;

namespace Shpack.Editor
{
    public static class ShpackImporter
    {
        const string Menu = "Tools/shpack/";

        [MenuItem(Menu + "Set Ambient Probe from JSON...")]
        static void AmbientFromDocumentMenu()
        {
            string path = EditorUtility.OpenFilePanel("shpack JSON document", "", "json");
            if (!string.IsNullOrEmpty(path)) Run(() => ShpackAmbient.FromDocument(path));
        }

        [MenuItem(Menu + "Set Ambient Probe from Selected Map")]
        static void AmbientFromMapMenu() { Run(() => ShpackAmbient.FromMap(Selection.activeObject, false)); }

        [MenuItem(Menu + "Set Ambient Probe and Sun from Selected Map")]
        static void AmbientAndSunFromMapMenu() { Run(() => ShpackAmbient.FromMap(Selection.activeObject, true)); }

        [MenuItem(Menu + "Set Ambient Probe from Selected Map", true)]
        [MenuItem(Menu + "Set Ambient Probe and Sun from Selected Map", true)]
        static bool MapIsSelected() { return Selection.activeObject is Cubemap || Selection.activeObject is Texture2D; }

        [MenuItem(Menu + "Set Baked Light Probes from JSON...")]
        static void BakedProbesMenu()
        {
            string path = EditorUtility.OpenFilePanel("shpack JSON document", "", "json");
            if (string.IsNullOrEmpty(path)) return;
            string asset = EditorUtility.SaveFilePanelInProject("Save the light probes", "ShpackLightProbes", "asset",
                                                                "The LightProbes asset the scene will use");
            if (!string.IsNullOrEmpty(asset)) Run(() => ShpackBakedProbes.FromDocument(path, asset));
        }

        // Confirms with the bake warning, runs, and reports: the result to the console, an
        // error in a dialog. Public so that the Mono test can drive a command as a menu does.
        public static bool Run(Func<string> command)
        {
            if (!EditorUtility.DisplayDialog("shpack", ShpackEditorScene.BakeWarning, "Apply", "Cancel")) return false;
            try
            {
                Debug.Log(command());
                Debug.LogWarning("shpack: " + ShpackEditorScene.BakeWarning);
                return true;
            }
            catch (Exception e)
            {
                EditorUtility.DisplayDialog("shpack", e.Message, "OK");
                return false;
            }
        }
    }
}
