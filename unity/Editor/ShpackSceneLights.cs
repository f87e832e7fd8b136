// ShpackSceneLights.cs - the Directional Lights of a document's lights (ShpackLight), made,
// updated or removed so that the scene holds exactly one per light (ShpackSceneLight marks
// them). Rotation, colour and intensity as lib/include/shpack/unity_light.h derives them.
using System.Collections.Generic;
using UnityEditor;
using UnityEngine;

namespace Shpack.Editor
{
    public static class ShpackSceneLights
    {
        // Makes the scene's shpack lights `lights`, in order. Returns how many there are.
        public static int Sync(List<ShpackLight> lights)
        {
            var existing = new Dictionary<int, ShpackSceneLight>();
            foreach (ShpackSceneLight marker in Object.FindObjectsOfType<ShpackSceneLight>())
            {
                if (marker.Index < lights.Count && !existing.ContainsKey(marker.Index)) existing[marker.Index] = marker;
                else Undo.DestroyObjectImmediate(marker.gameObject);  // no longer in the document, or a duplicate
            }
            for (int k = 0; k < lights.Count; ++k)
            {
                ShpackSceneLight marker;
                Light light = existing.TryGetValue(k, out marker) ? Existing(marker) : Create(k);
                Set(light, lights[k]);
            }
            return lights.Count;
        }

        static Light Existing(ShpackSceneLight marker)
        {
            Light light = marker.GetComponent<Light>();
            if (light == null) light = Undo.AddComponent<Light>(marker.gameObject);
            Undo.RecordObject(light, "shpack: update light");
            Undo.RecordObject(light.transform, "shpack: update light");
            return light;
        }

        static Light Create(int index)
        {
            var gameObject = new GameObject(index == 0 ? "shpack sun" : "shpack light " + index);
            Light light = gameObject.AddComponent<Light>();
            light.type = LightType.Directional;
            light.shadows = LightShadows.Soft;
            gameObject.AddComponent<ShpackSceneLight>().Index = index;
            Undo.RegisterCreatedObjectUndo(gameObject, "shpack: create light");
            return light;
        }

        static void Set(Light light, ShpackLight from)
        {
            light.transform.rotation = from.Rotation();
            light.color = from.LightColor();
            light.intensity = (float)from.Intensity;
        }
    }
}
