// ShpackMonoTestEditor.cs - the editor commands on the stubbed scene: each asks first with the
// bake warning, goes through Undo and marks the scene dirty; the ambient probe takes the
// document's or the conversion's floats; the document's lights become Directional Lights,
// one per light however often a document is applied (the sun listed again in "lights" is not
// a second light, a document without lights removes them); the baked probes are saved as a
// LightProbes asset that a scene component re-applies as a reload would.
using System.IO;
using Newtonsoft.Json.Linq;
using Shpack;
using Shpack.Editor;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.Rendering;

static partial class ShpackMonoTest
{
    static void CheckEditor()
    {
        CheckAmbientAndLights();
        CheckAmbientFromMaps();
        CheckBakedProbes();
        CheckCancelAndErrors();
    }

    // Runs an editor command as its menu does, which must succeed after showing the warning,
    // record an undo step and mark the scene dirty.
    static void RunCommand(System.Func<string> command, string what)
    {
        int dialogs = EditorUtility.Dialogs.Count, undo = Undo.Log.Count, dirty = EditorSceneManager.DirtyMarks;
        Check(ShpackImporter.Run(command), what + " succeeds: " + string.Join(" | ", EditorUtility.Dialogs));
        Check(EditorUtility.Dialogs.Count == dialogs + 1 && EditorUtility.Dialogs[dialogs] == ShpackEditorScene.BakeWarning,
              what + " asks first with the bake warning");
        Check(Undo.Log.Count > undo && Undo.Log[undo].StartsWith("group "), what + " is an undo step");
        Check(EditorSceneManager.DirtyMarks == dirty + 1, what + " marks the scene dirty");
    }

    static ShpackSceneLight[] SceneLights()
    {
        ShpackSceneLight[] lights = Object.FindObjectsOfType<ShpackSceneLight>();
        System.Array.Sort(lights, (a, b) => a.Index.CompareTo(b.Index));
        return lights;
    }

    static void CheckLight(ShpackSceneLight marker, ShpackLight want, string what)
    {
        Light light = marker.GetComponent<Light>();
        Check(light != null && light.type == LightType.Directional, what + " is a directional light");
        if (light == null) return;
        Quaternion q = light.transform.rotation;
        CheckSameFloats(new[] { q.x, q.y, q.z, q.w }, System.Array.ConvertAll(want.Quaternion, v => (float)v), what + " rotation");
        CheckSameFloats(new[] { light.color.r, light.color.g, light.color.b }, System.Array.ConvertAll(want.ColorSrgb, v => (float)v),
                        what + " color (sRGB)");
        CheckSameFloats(new[] { light.intensity }, new[] { (float)want.Intensity }, what + " intensity");
    }

    static void CheckAmbientAndLights()
    {
        string sunJson = Path.Combine(work, "sun.json");
        ShpackDocumentData document = ShpackDocument.LoadFile(sunJson);
        RunCommand(() => ShpackAmbient.FromDocument(sunJson), "ambient probe from a document with a sun");
        Check(RenderSettings.ambientMode == AmbientMode.Custom, "ambient mode Custom");
        CheckProbe(RenderSettings.ambientProbe, document.Probes[0].UnitySh, "ambientProbe");
        Check(Undo.Log.Contains("record RenderSettings"), "RenderSettings recorded for undo");
        Check(Undo.Log.Contains("create shpack sun"), "the sun's light created through Undo");
        ShpackSceneLight[] lights = SceneLights();
        Check(lights.Length == 1, "one light for the sun, got " + lights.Length);
        if (lights.Length == 1) CheckLight(lights[0], document.Lights[0], "shpack sun");

        RunCommand(() => ShpackAmbient.FromDocument(sunJson), "the same document again");
        Check(SceneLights().Length == 1, "applied twice, still one light");
        Check(Undo.Log.Contains("record Light") && Undo.Log.Contains("record Transform"), "the existing light updated through Undo");

        // "lights" holding the sun again and one more: two lights, the sun counted once.
        JObject json = JObject.Parse(File.ReadAllText(sunJson));
        var other = (JObject)json["sun"].DeepClone();
        other["direction"] = new JArray(0.0, 1.0, 0.0);
        other["unity_light"]["quaternion"] = new JArray(0.5, 0.5, 0.5, 0.5);
        json["lights"] = new JArray(json["sun"].DeepClone(), other);
        string lightsJson = Path.Combine(work, "lights.json");
        File.WriteAllText(lightsJson, json.ToString());
        RunCommand(() => ShpackAmbient.FromDocument(lightsJson), "a document with a lights array");
        lights = SceneLights();
        Check(lights.Length == 2, "the sun and one more light, got " + lights.Length);
        if (lights.Length == 2) CheckLight(lights[1], ShpackDocument.LoadFile(lightsJson).Lights[1], "shpack light 1");

        // A document without lights: its SH holds all the light, so shpack's lights go.
        string plain = Path.Combine(work, "sky.json");
        RunCommand(() => ShpackAmbient.FromDocument(plain), "a document without lights");
        Check(SceneLights().Length == 0, "no shpack light left");
        CheckProbe(RenderSettings.ambientProbe, ShpackDocument.ReadFile(plain)[0].UnitySh, "ambientProbe of sky.json");
    }

    static void CheckAmbientFromMaps()
    {
        Cubemap cubemap = MakeCubemap(8);
        ShpackResult expected = ShpackNative.ConvertCubemap(cubemap);
        RunCommand(() => ShpackAmbient.FromMap(cubemap, false), "ambient probe from a Cubemap");
        CheckProbe(RenderSettings.ambientProbe, expected.UnitySh, "ambientProbe of the cubemap");

        float[] sky = MakeSky(SkyWidth, SkyHeight);
        var texture = new Texture2D(SkyWidth, SkyHeight, TextureFormat.RGBAFloat, false) { name = "sky" };
        texture.SetPixels(BottomUpColors(sky, SkyWidth, SkyHeight));
        ShpackResult withSun = ShpackNative.ConvertEquirect(sky, SkyWidth, SkyHeight, 3, new ShpackOptions { ExtractSun = true });
        RunCommand(() => ShpackAmbient.FromMap(texture, true), "ambient probe and sun from an equirect texture");
        CheckProbe(RenderSettings.ambientProbe, withSun.UnitySh, "ambientProbe of the texture without its sun");
        ShpackSceneLight[] lights = SceneLights();
        Check(lights.Length == 1, "the texture's sun is one light, got " + lights.Length);
        if (lights.Length == 1 && withSun.Sun != null) CheckLight(lights[0], withSun.Sun, "the texture's sun");
    }

    static void CheckBakedProbes()
    {
        string json = Path.Combine(work, "sky.json");
        float[] want = ShpackDocument.ReadFile(json)[0].UnitySh;
        var positions = new[] { new Vector3(0, 1, 0), new Vector3(5, 1, 0), new Vector3(0, 1, 5) };
        LightmapSettings.lightProbes = new LightProbes(positions);
        const string asset = "Assets/ShpackLightProbes.asset";
        RunCommand(() => ShpackBakedProbes.FromDocument(json, asset), "baked probes from a document");
        UnityEngine.Object stored;
        var saved = AssetDatabase.Assets.TryGetValue(asset, out stored) ? stored as LightProbes : null;
        Check(saved != null, "a LightProbes asset saved at " + asset);
        Check(LightmapSettings.lightProbes == saved, "the scene uses the saved probes");
        ShpackLightProbes[] holders = Object.FindObjectsOfType<ShpackLightProbes>();
        Check(holders.Length == 1 && holders[0].Probes == saved, "one ShpackLightProbes in the scene references the asset");
        if (saved == null || holders.Length != 1) return;
        foreach (SphericalHarmonicsL2 probe in saved.bakedProbes) CheckProbe(probe, want, "saved bakedProbes");

        // A reload: the scene comes back with the probes of its LightingData, and the
        // component, enabled again, puts the asset's back.
        LightmapSettings.lightProbes = new LightProbes(positions);
        holders[0].Apply();
        foreach (SphericalHarmonicsL2 probe in LightmapSettings.lightProbes.bakedProbes) CheckProbe(probe, want, "bakedProbes after a reload");
        RunCommand(() => ShpackBakedProbes.FromDocument(json, asset), "baked probes again");
        Check(Object.FindObjectsOfType<ShpackLightProbes>().Length == 1, "still one ShpackLightProbes");
    }

    static void CheckCancelAndErrors()
    {
        SphericalHarmonicsL2 before = RenderSettings.ambientProbe;
        EditorUtility.Answer = false;
        Check(!ShpackImporter.Run(() => ShpackAmbient.FromDocument(Path.Combine(work, "sun.json"))), "cancelled");
        EditorUtility.Answer = true;
        Check(SceneLights().Length == 1 && Bits(RenderSettings.ambientProbe[0, 0]) == Bits(before[0, 0]), "a cancelled command changes nothing");

        string bad = Path.Combine(work, "bad.json");
        Check(!ShpackImporter.Run(() => ShpackAmbient.FromDocument(bad)), "a bad document fails");
        Check(EditorUtility.Dialogs[EditorUtility.Dialogs.Count - 1].StartsWith(bad + ": "), "its error is shown in a dialog");
    }
}
