// Relative luminance of linear Rec. 709 / sRGB primaries (ITU-R BT.709).
float luminance(vec3 rgb) { return dot(rgb, vec3(0.2126, 0.7152, 0.0722)); }
