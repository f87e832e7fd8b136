// ShpackBakedProbes.cs - the scene's baked light probes from a shpack document, saved as a
// LightProbes asset that a ShpackLightProbes component of the scene re-applies on every load
// (ShpackLightProbes.cs says why the LightingData asset cannot hold them).
//
// A `convert` document holds one probe: every light probe takes it. A `bake` document holds
// one per position: each light probe takes the document probe nearest to it (a Light Probe
// Group baked at the same positions matches exactly). The coefficients are Unity's own
// (sphericalHarmonicsL2), assigned as they are.
using System;
using System.Collections.Generic;
using UnityEditor;
using UnityEngine;
using UnityEngine.Rendering;

namespace Shpack.Editor
{
    public static class ShpackBakedProbes
    {
        // Writes the probes of `documentPath` into a copy of the scene's light probes, saved at
        // `assetPath` (under Assets/), and makes the scene use it. Returns what it did.
        public static string FromDocument(string documentPath, string assetPath)
        {
            LightProbes scene = LightmapSettings.lightProbes;
            if (scene == null || scene.count == 0)
                throw new InvalidOperationException("the scene has no baked light probes; bake a Light Probe Group first");
            List<ShpackProbeData> probes = ShpackDocument.ReadFile(documentPath);
            if (probes.Count == 0) throw new FormatException(documentPath + ": holds no probes");
            LightProbes saved = UnityEngine.Object.Instantiate(scene);  // positions and tetrahedra of the scene
            Vector3[] positions = saved.positions;
            SphericalHarmonicsL2[] coefficients = saved.bakedProbes;
            for (int k = 0; k < coefficients.Length; ++k)
                coefficients[k] = Nearest(probes, positions[k]).ToSphericalHarmonicsL2();
            saved.bakedProbes = coefficients;  // the setter copies the array into the object
            AssetDatabase.CreateAsset(saved, assetPath);
            AssetDatabase.SaveAssets();
            return ShpackEditorScene.Edit("shpack: set baked light probes", () =>
            {
                ShpackLightProbes holder = Holder();
                Undo.RecordObject(holder, "shpack: set baked light probes");
                holder.Probes = saved;
                holder.Apply();
                return "shpack: " + coefficients.Length + " baked light probes set from " + documentPath + ", saved as " + assetPath;
            });
        }

        // The scene's one ShpackLightProbes, made if there is none.
        static ShpackLightProbes Holder()
        {
            ShpackLightProbes[] found = UnityEngine.Object.FindObjectsOfType<ShpackLightProbes>();
            if (found.Length > 0) return found[0];
            var gameObject = new GameObject("shpack light probes");
            ShpackLightProbes holder = gameObject.AddComponent<ShpackLightProbes>();
            Undo.RegisterCreatedObjectUndo(gameObject, "shpack: set baked light probes");
            return holder;
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
