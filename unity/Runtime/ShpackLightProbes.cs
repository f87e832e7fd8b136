// ShpackLightProbes.cs - keeps a scene's light probes those of a saved LightProbes asset.
//
// The baked probes Unity keeps for a scene live in its LightingData asset, written only by
// Unity's own bake; coefficients assigned to LightmapSettings.lightProbes in the Editor are
// gone when the scene is reloaded. The editor's "Set Baked Light Probes" saves them as a
// LightProbes asset instead, and this component, saved with the scene and referencing that
// asset, assigns it to LightmapSettings.lightProbes whenever it is enabled: on every load,
// in the Editor (ExecuteAlways) and in a player.
using UnityEngine;

namespace Shpack
{
    [ExecuteAlways]
    public sealed class ShpackLightProbes : MonoBehaviour
    {
        public LightProbes Probes;

        void OnEnable() { Apply(); }

        public void Apply()
        {
            if (Probes != null) LightmapSettings.lightProbes = Probes;
        }
    }
}
