// ShpackLightmap.hlsl - E(n)/pi at a texel of a shpack SH lightmap, for a unit world-space
// normal n (Unity's frame). Each texture holds, per texel, one of Unity's SH shader vectors
// (unity_SHAr, ...): they are sampled with bilinear filtering at the lightmap UV (uv2 in
// Unity) and evaluated as UnityCG.cginc's SHEvalLinearL0L1 (+ SHEvalLinearL2) does for a
// probe. For an L2 lightmap, #define SHPACK_LIGHTMAP_L2 1 before including this file.
#ifndef SHPACK_LIGHTMAP_INCLUDED
#define SHPACK_LIGHTMAP_INCLUDED

Texture2D<float4> _ShpackSHAr, _ShpackSHAg, _ShpackSHAb;
#if SHPACK_LIGHTMAP_L2
Texture2D<float4> _ShpackSHBr, _ShpackSHBg, _ShpackSHBb, _ShpackSHC;
#endif
SamplerState sampler_linear_clamp;

float3 ShpackLightmapSH(float2 lightmapUV, float3 n)
{
    float4 n1 = float4(n, 1.0f);
    float4 ar = _ShpackSHAr.SampleLevel(sampler_linear_clamp, lightmapUV, 0);
    float4 ag = _ShpackSHAg.SampleLevel(sampler_linear_clamp, lightmapUV, 0);
    float4 ab = _ShpackSHAb.SampleLevel(sampler_linear_clamp, lightmapUV, 0);
    float3 e = float3(dot(ar, n1), dot(ag, n1), dot(ab, n1));
#if SHPACK_LIGHTMAP_L2
    float4 q = n.xyzz * n.yzzx;
    e += float3(dot(_ShpackSHBr.SampleLevel(sampler_linear_clamp, lightmapUV, 0), q),
                dot(_ShpackSHBg.SampleLevel(sampler_linear_clamp, lightmapUV, 0), q),
                dot(_ShpackSHBb.SampleLevel(sampler_linear_clamp, lightmapUV, 0), q));
    e += _ShpackSHC.SampleLevel(sampler_linear_clamp, lightmapUV, 0).rgb * (n.x * n.x - n.y * n.y);
#endif
    return e;  // E(n)/pi: times the albedo, the diffuse light
}

#endif  // SHPACK_LIGHTMAP_INCLUDED
