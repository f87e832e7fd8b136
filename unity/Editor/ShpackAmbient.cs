// ShpackAmbient.cs - the scene's ambient probe (RenderSettings.ambientProbe) from a shpack
// document or from a map converted in memory, with the map's lights as Directional Lights.
//
// The ambient mode becomes Custom: in Skybox mode Unity derives the ambient probe from the
// skybox material itself, and in Gradient or Color mode it does not read the probe.
using System;
using System.Collections.Generic;
using UnityEngine;
using UnityEngine.Rendering;

namespace Shpack.Editor
{
    public static class ShpackAmbient
    {
        // The document's (single) probe, and its lights. Returns what it did.
        public static string FromDocument(string path)
        {
            ShpackDocumentData document = ShpackDocument.LoadFile(path);
            if (document.Probes.Count != 1)
                throw new FormatException(path + ": holds " + document.Probes.Count + " probes; the ambient probe takes one");
            return Apply(document.Probes[0].ToSphericalHarmonicsL2(), document.Lights, path);
        }

        // A Cubemap, or a Texture2D in any layout detected from its size (an equirect one with
        // extractSun: its sun becomes a Directional Light). Both must be Read/Write enabled.
        public static string FromMap(UnityEngine.Object map, bool extractSun)
        {
            var options = new ShpackOptions { ExtractSun = extractSun };
            var cubemap = map as Cubemap;
            var texture = map as Texture2D;
            if (cubemap == null && texture == null) throw new ArgumentException("select a Cubemap or a Texture2D");
            ShpackResult result = cubemap != null ? ShpackNative.ConvertCubemap(cubemap, options)
                                                  : ShpackNative.ConvertTexture(texture, ShpackLayout.Auto, options);
            var lights = new List<ShpackLight>();
            if (result.Sun != null) lights.Add(result.Sun);
            return Apply(result.ToSphericalHarmonicsL2(), lights, map.name);
        }

        // Every light of the source replaces the ones shpack made before: a map converted
        // whole (no lights) removes them, since its SH already holds their light.
        static string Apply(SphericalHarmonicsL2 probe, List<ShpackLight> lights, string source)
        {
            return ShpackEditorScene.Edit("shpack: set ambient probe", () =>
            {
                ShpackEditorScene.RecordRenderSettings("shpack: set ambient probe");
                RenderSettings.ambientMode = AmbientMode.Custom;
                RenderSettings.ambientProbe = probe;
                int count = ShpackSceneLights.Sync(lights);
                return "shpack: ambient probe set from " + source +
                       (count == 0 ? "" : ", with " + count + (count == 1 ? " directional light" : " directional lights"));
            });
        }
    }
}
