using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace HeadGait.Tooling
{
    /// <summary>
    /// The materials of the package's primitives (mannequin, Legs floor, study scene) and their one shader, which renders
    /// in the built-in pipeline and in URP alike, so nothing shows magenta in Unity 6's URP VR template (built-in
    /// Default-Material and Standard do there). Why it works in both: the shader's only SubShader has no "RenderPipeline"
    /// tag (a SubShader with one is used only under the pipeline whose tag matches; none means every pipeline), and its
    /// colour Pass has no "LightMode" tag, which the built-in pipeline draws as "Always" and an SRP as "SRPDefaultUnlit",
    /// one of the tags URP's DrawObjectsPass draws (with UniversalForward and UniversalForwardOnly). A "ShadowCaster" pass
    /// gives both pipelines' shadow maps the primitives, each with that pipeline's own shadow bias (URP's written out after
    /// its ShadowCasterPass.hlsl, chosen by what only URP sets), and "DepthOnly" and "DepthNormals" passes URP's depth
    /// prepass (under depth priming URP draws opaques with ZTest Equal against it, so an opaque missing there is not
    /// drawn). Every pass includes only UnityCG.cginc, which ships with the editor whatever the pipeline. Lighting is a
    /// fixed key light and a sky/ground term in the shader itself, so the primitives read the same under any scene lighting
    /// and pipeline.
    /// </summary>
    public static class PrimitiveMaterials
    {
        public const string Folder = "Runtime/Materials";
        public const string ShaderPath = Folder + "/HeadGait Primitive.shader";
        public const string ShaderGuid = "1edd98aa9f384f6a91a7333e80d769c1";
        public const string ShaderName = "HeadGait/Primitive";
        /// <summary>A shader's fileID in its imported .shader file (class 48).</summary>
        public const long ShaderFileId = 4800000;
        /// <summary>A material's fileID in its .mat file (class 21).</summary>
        public const long MaterialFileId = 2100000;

        public sealed class Material
        {
            public readonly string Name, Guid;
            public readonly double R, G, B;
            public Material(string name, string guid, double r, double g, double b) { Name = name; Guid = guid; R = r; G = g; B = b; }
            public string Path => Folder + "/HeadGait " + Name + ".mat";
            /// <summary>The reference a renderer's m_Materials entry holds.</summary>
            public string Ref => UnityYaml.Ref(MaterialFileId, Guid, 2);
        }

        public static readonly Material Mannequin = new Material("Mannequin", "8722fdafbca7477baa3e8de6a62cbb7d", 0.72, 0.76, 0.82);
        public static readonly Material Ground = new Material("Ground", "db45a5a341f043c7a7b4b6ea1bf8986f", 0.52, 0.55, 0.5);
        public static readonly Material Pit = new Material("Pit", "b2cda0fe3574459e8039e2ba8685946c", 0.16, 0.15, 0.14);
        public static readonly Material Bridge = new Material("Bridge", "11335340874b42d9b37ae1ed2102a19e", 0.55, 0.4, 0.26);
        public static readonly Material Path = new Material("Path", "a9d5da9b6a6c4b59b7c40b00e6ef4669", 0.85, 0.82, 0.7);
        public static readonly Material BlockAvatar = new Material("Block Avatar", "a1ac235505554ee19011d46c182d3271", 0.35, 0.5, 0.75);
        public static readonly Material Marker = new Material("Marker", "9aecf9c3170e4c2fb129191aac83587f", 0.95, 0.55, 0.15);

        public static readonly IReadOnlyList<Material> All = new[] { Mannequin, Ground, Pit, Bridge, Path, BlockAvatar, Marker };

        /// <summary>Writes the shader and every material (with their fixed GUIDs) under the package; returns the paths.</summary>
        public static List<string> WriteAll(string package)
        {
            var written = new List<string>();
            void Write(string relative, string text, string guid)
            {
                string path = System.IO.Path.Combine(package, relative);
                Directory.CreateDirectory(System.IO.Path.GetDirectoryName(path));
                string folderMeta = System.IO.Path.GetDirectoryName(path) + ".meta";
                if (!File.Exists(folderMeta)) File.WriteAllText(folderMeta, UnityMeta.Text(System.IO.Path.GetDirectoryName(path), System.Guid.NewGuid().ToString("N")));
                File.WriteAllText(path, text, new UTF8Encoding(false));
                string meta = path + ".meta";
                if (!File.Exists(meta) || UnityMeta.GuidOf(meta) != guid) File.WriteAllText(meta, UnityMeta.Text(path, guid));
                written.Add(relative);
            }
            Write(ShaderPath, ShaderSource, ShaderGuid);
            foreach (var m in All) Write(m.Path, MaterialYaml(m), m.Guid);
            return written;
        }

        static string N(double v) => v.ToString("0.###", CultureInfo.InvariantCulture);

        /// <summary>A Material (class 21) of the primitive shader with its colour, laid out as Unity 6 saves materials.</summary>
        public static string MaterialYaml(Material m)
        {
            var sb = new StringBuilder(UnityYaml.Header);
            sb.Append(UnityYaml.Document(21, MaterialFileId, "Material"));
            sb.Append("  serializedVersion: 8\n  m_ObjectHideFlags: 0\n  m_CorrespondingSourceObject: {fileID: 0}\n  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n");
            sb.Append("  m_Name: HeadGait ").Append(m.Name).Append('\n');
            sb.Append("  m_Shader: ").Append(UnityYaml.Ref(ShaderFileId, ShaderGuid, 3)).Append('\n');
            sb.Append("  m_Parent: {fileID: 0}\n  m_ModifiedSerializedProperties: 0\n  m_ValidKeywords: []\n  m_InvalidKeywords: []\n");
            sb.Append("  m_LightmapFlags: 4\n  m_EnableInstancingVariants: 1\n  m_DoubleSidedGI: 0\n  m_CustomRenderQueue: -1\n");
            sb.Append("  stringTagMap: {}\n  disabledShaderPasses: []\n  m_LockedProperties: \n  m_SavedProperties:\n    serializedVersion: 3\n");
            sb.Append("    m_TexEnvs: []\n    m_Ints: []\n    m_Floats: []\n    m_Colors:\n");
            sb.Append("    - _Color: {r: ").Append(N(m.R)).Append(", g: ").Append(N(m.G)).Append(", b: ").Append(N(m.B)).Append(", a: 1}\n");
            sb.Append("  m_BuildTextureStacks: []\n  m_AllowLocking: 1\n");
            return sb.ToString();
        }

        /// <summary>
        /// The shader: opaque, single-pass-instanced stereo ready (Quest), no textures, no pipeline includes. Besides the
        /// colour pass, a ShadowCaster pass (both pipelines' shadow maps, each with its own bias) and URP's DepthOnly and
        /// DepthNormals passes (its depth prepass; under depth priming an opaque not drawn there is not drawn at all).
        /// </summary>
        public const string ShaderSource =
@"// Generated by `headgait clips` (dotnet/Shared/GaitAssets/PrimitiveMaterials.cs). Renders in the built-in pipeline and
// in URP: no RenderPipeline tag on the SubShader, no LightMode tag on the colour Pass (built-in draws it as Always, URP as
// SRPDefaultUnlit), only UnityCG.cginc included. Shading is a fixed key light plus sky/ground ambient.
// ShadowCaster: both pipelines render their shadow maps from it (built-in also its camera depth texture), each with its
// own bias. Built-in: UnityCG's macros (unity_LightShadowBias, _WorldSpaceLightPos0). URP: its caster-side bias as URP's
// ShadowCasterPass.hlsl applies it, written out here without URP's include files: the globals URP sets before every
// shadow slice (_ShadowBias: x depth, y normal bias; _LightDirection; _LightPosition for spot and point lights, under
// URP's _CASTING_PUNCTUAL_LIGHT_SHADOW keyword) and the clamp to the shadow near plane. URP's path is taken only where
// URP alone can have put the shader: in the variant with that keyword (URP's spot and point light slices, which set
// _ShadowBias and _LightPosition but, in recent URP, not _LightDirection), and otherwise when _LightDirection is set (to a
// unit vector; URP sets it before every main light cascade). Under built-in both are off and zero, which keeps UnityCG's
// position exactly; under URP the position is URP's alone, so no built-in bias the engine may leave set is added to it.
// DepthOnly, DepthNormals: URP's depth prepass. With depth priming URP draws opaques with ZTest Equal against that
// prepass, so without them the primitives would not be drawn at all; they also put the primitives in URP's depth and
// normals textures (SSAO, depth of field). They run the colour pass's vertex function (CGINCLUDE), so the depths are
// equal. DepthNormals writes the normalized world-space normal, as URP's Lit does there; it writes no rendering
// layers (_WRITE_RENDERING_LAYERS) and has no octahedron-packed variant. The built-in pipeline draws neither pass.
// Written against Unity's sources and manual; not compiled here (no Unity editor).
Shader ""HeadGait/Primitive""
{
    Properties
    {
        _Color (""Color"", Color) = (0.8, 0.8, 0.8, 1)
    }
    SubShader
    {
        Tags { ""RenderType"" = ""Opaque"" ""Queue"" = ""Geometry"" }

        // Shared by every pass: the colour, DepthOnly and DepthNormals passes use the same vertex function, so the
        // prepass's depths equal the colour pass's.
        CGINCLUDE
        #include ""UnityCG.cginc""

        struct appdata
        {
            float4 vertex : POSITION;
            float3 normal : NORMAL;
            UNITY_VERTEX_INPUT_INSTANCE_ID
        };

        struct v2f
        {
            float4 pos : SV_POSITION;
            float3 normal : TEXCOORD0;
            UNITY_VERTEX_OUTPUT_STEREO
        };

        v2f vert(appdata v)
        {
            v2f o;
            UNITY_SETUP_INSTANCE_ID(v);
            UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
            o.pos = UnityObjectToClipPos(v.vertex);
            o.normal = UnityObjectToWorldNormal(v.normal);
            return o;
        }
        ENDCG

        Pass
        {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_instancing

            fixed4 _Color;

            fixed4 frag(v2f i) : SV_Target
            {
                float3 n = normalize(i.normal);
                float key = saturate(dot(n, normalize(float3(0.4, 0.8, -0.45))));
                float sky = 0.5 + 0.5 * n.y;
                return fixed4(_Color.rgb * (0.3 + 0.25 * sky + 0.55 * key), 1);
            }
            ENDCG
        }

        Pass
        {
            Name ""ShadowCaster""
            Tags { ""LightMode"" = ""ShadowCaster"" }

            CGPROGRAM
            #pragma vertex vertShadow
            #pragma fragment fragShadow
            #pragma multi_compile_shadowcaster
            #pragma multi_compile_instancing
            // URP turns it on for its spot and point lights' shadow slices and off for the main light's; the built-in
            // pipeline never turns it on, so it draws the variant without it.
            #pragma multi_compile_vertex _ _CASTING_PUNCTUAL_LIGHT_SHADOW

            // URP's shadow-caster globals (ShadowUtils.SetupShadowCasterConstantBuffer, before every shadow slice). The
            // built-in pipeline never sets them, so there they read zero.
            float4 _ShadowBias;     // x: depth bias, y: normal bias, in world units, both negative or zero
            float3 _LightDirection; // unit vector from the surface toward a directional light
            float3 _LightPosition;  // the light's world position (spot and point lights)

            struct v2f_shadow
            {
                V2F_SHADOW_CASTER;
                UNITY_VERTEX_OUTPUT_STEREO
            };

            // Only URP turns the keyword on (its spot and point light slices) and sets _LightDirection (to a unit vector,
            // before every main light cascade; its spot and point light slices may leave it unset).
            bool UrpShadowPass()
            {
            #if defined(_CASTING_PUNCTUAL_LIGHT_SHADOW)
                return true;
            #else
                return dot(_LightDirection, _LightDirection) > 0.5;
            #endif
            }

            // URP's caster-side bias: the vertex moves away from the light by the depth bias and inward along its normal by
            // the normal bias times (1 - N.L), in world space; then a caster between the light and the shadow near plane is
            // flattened onto that plane instead of clipped.
            float4 UrpShadowCasterPos(float4 vertex, float3 normal)
            {
                float3 worldPos = mul(unity_ObjectToWorld, float4(vertex.xyz, 1)).xyz;
                float3 worldNormal = UnityObjectToWorldNormal(normal);
            #if defined(_CASTING_PUNCTUAL_LIGHT_SHADOW)
                float3 toLight = normalize(_LightPosition - worldPos);
            #else
                float3 toLight = _LightDirection;
            #endif
                float turnedAway = 1 - saturate(dot(toLight, worldNormal));
                worldPos += toLight * _ShadowBias.x + worldNormal * (turnedAway * _ShadowBias.y);
                float4 clipPos = mul(UNITY_MATRIX_VP, float4(worldPos, 1));
            #if defined(UNITY_REVERSED_Z)
                clipPos.z = min(clipPos.z, UNITY_NEAR_CLIP_VALUE);
            #else
                clipPos.z = max(clipPos.z, UNITY_NEAR_CLIP_VALUE);
            #endif
                return clipPos;
            }

            v2f_shadow vertShadow(appdata v)
            {
                v2f_shadow o;
                UNITY_SETUP_INSTANCE_ID(v);
                UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
                // The built-in pipeline's bias (unity_LightShadowBias, _WorldSpaceLightPos0); under URP the position is
                // replaced whole, so nothing of it is added to URP's own.
                TRANSFER_SHADOW_CASTER_NORMALOFFSET(o)
                if (UrpShadowPass())
                    o.pos = UrpShadowCasterPos(v.vertex, v.normal);
                return o;
            }

            float4 fragShadow(v2f_shadow i) : SV_Target
            {
                SHADOW_CASTER_FRAGMENT(i)
            }
            ENDCG
        }

        Pass
        {
            Name ""DepthOnly""
            Tags { ""LightMode"" = ""DepthOnly"" }
            ZWrite On
            ColorMask R

            CGPROGRAM
            #pragma vertex vert
            #pragma fragment fragDepth
            #pragma multi_compile_instancing

            float4 fragDepth(v2f i) : SV_Target
            {
                return float4(i.pos.z, 0, 0, 0);
            }
            ENDCG
        }

        Pass
        {
            Name ""DepthNormals""
            Tags { ""LightMode"" = ""DepthNormals"" }
            ZWrite On

            CGPROGRAM
            #pragma vertex vert
            #pragma fragment fragNormals
            #pragma multi_compile_instancing

            float4 fragNormals(v2f i) : SV_Target
            {
                return float4(normalize(i.normal), 0);
            }
            ENDCG
        }
    }
    Fallback Off
}
";
    }
}
