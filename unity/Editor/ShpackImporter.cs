// ShpackImporter.cs - Editor menu items that put a shpack JSON document into a scene's lighting:
//
//   Tools > shpack > Set Ambient Probe from JSON...     RenderSettings.ambientProbe (mode Custom)
//   Tools > shpack > Set Baked Light Probes from JSON... LightmapSettings.lightProbes.bakedProbes
//
// A `shpack convert` document holds one probe: it becomes the ambient probe, or every baked
// light probe. A `shpack bake` document holds one per position: each baked probe takes the
// document probe nearest to it (a light probe group baked at the same positions matches
// exactly). The coefficients are Unity's own (sphericalHarmonicsL2), assigned as they are.
using System;
using System.Collections.Generic;
using UnityEditor;
using UnityEngine;
using UnityEngine.Rendering;

namespace Shpack.Editor
{
    public static class ShpackImporter
    {
        [MenuItem("Tools/shpack/Set Ambient Probe from JSON...")]
        static void SetAmbientProbeMenu()
        {
            string path = EditorUtility.OpenFilePanel("shpack JSON document", "", "json");
            if (string.IsNullOrEmpty(path)) return;
            Report(() => SetAmbientProbe(path));
        }

        [MenuItem("Tools/shpack/Set Baked Light Probes from JSON...")]
        static void SetBakedProbesMenu()
        {
            string path = EditorUtility.OpenFilePanel("shpack JSON document", "", "json");
            if (string.IsNullOrEmpty(path)) return;
            Report(() => SetBakedProbes(path));
        }

        static void Report(Func<string> action)
        {
            try
            {
                Debug.Log(action());
            }
            catch (Exception e)
            {
                EditorUtility.DisplayDialog("shpack", e.Message, "OK");
            }
        }

        // Sets the scene's ambient lighting to the document's (single) probe. Returns what it did.
        public static string SetAmbientProbe(string path)
        {
            List<ShpackProbeData> probes = ShpackDocument.ReadFile(path);
            if (probes.Count != 1)
                throw new FormatException(path + ": holds " + probes.Count + " probes; the ambient probe takes one");
            RenderSettings.ambientMode = AmbientMode.Custom;
            RenderSettings.ambientProbe = probes[0].ToSphericalHarmonicsL2();
            return "shpack: ambient probe set from " + path;
        }

        // Replaces the coefficients of the scene's baked light probes. Returns what it did.
        public static string SetBakedProbes(string path)
        {
            LightProbes lightProbes = LightmapSettings.lightProbes;
            if (lightProbes == null || lightProbes.count == 0)
                throw new InvalidOperationException("the scene has no baked light probes; bake a Light Probe Group first");
            List<ShpackProbeData> probes = ShpackDocument.ReadFile(path);
            if (probes.Count == 0) throw new FormatException(path + ": holds no probes");
            Vector3[] positions = lightProbes.positions;
            SphericalHarmonicsL2[] coefficients = lightProbes.bakedProbes;
            for (int k = 0; k < coefficients.Length; ++k)
                coefficients[k] = Nearest(probes, positions[k]).ToSphericalHarmonicsL2();
            lightProbes.bakedProbes = coefficients;  // the setter copies the array into the asset
            return "shpack: " + coefficients.Length + " baked light probes set from " + path;
        }

        static ShpackProbeData Nearest(List<ShpackProbeData> probes, Vector3 position)
        {
            ShpackProbeData best = probes[0];
            float bestDistance = float.PositiveInfinity;
            foreach (ShpackProbeData probe in probes)
            {
                float d = (probe.Position - position).sqrMagnitude;
                if (d < bestDistance) { bestDistance = d; best = probe; }
            }
            return best;
        }
    }
}
