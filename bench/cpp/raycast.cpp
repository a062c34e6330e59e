// A plain single-threaded ray caster of MIT 6.837 Assignment 1, written as a course solution
// would be: the scene read with >> into a group of spheres, one ray per pixel tested against
// every sphere (a Group's intersect loops its objects), the colour and depth images kept in
// memory and written as uncompressed 24-bit TGA a byte at a time (as the course's image code does). It is the baseline the project's whole-command
// time is compared with (scripts/command-vs-cpp.sh); it is not part of the product.
//
//   raycast -input scene.txt -size W H -output colour.tga -depth DMIN DMAX depth.tga
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

struct Vec3 { double x, y, z; };
static Vec3 sub(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
static Vec3 add(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
static Vec3 mul(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
static double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
static Vec3 normalized(Vec3 a) { return mul(a, 1.0 / std::sqrt(dot(a, a))); }

struct Sphere { Vec3 center; double radius; int material; };

struct Hit { double t; int material; };

static bool intersect(const Sphere &s, Vec3 origin, Vec3 direction, double tmin, Hit &hit) {
  Vec3 oc = sub(origin, s.center);
  double b = 2.0 * dot(direction, oc);
  double c = dot(oc, oc) - s.radius * s.radius;
  double disc = b * b - 4.0 * c;
  if (disc < 0) return false;
  double root = std::sqrt(disc);
  double t = (-b - root) / 2.0;
  if (t < tmin) t = (-b + root) / 2.0;
  if (t < tmin || t >= hit.t) return false;
  hit.t = t;
  hit.material = s.material;
  return true;
}

static void expect(std::ifstream &in, const char *word) {
  std::string token;
  in >> token;
  if (token != word) { std::fprintf(stderr, "expected %s, found %s\n", word, token.c_str()); std::exit(1); }
}

static Vec3 read_vec(std::ifstream &in) { Vec3 v; in >> v.x >> v.y >> v.z; return v; }

static void read_group(std::ifstream &in, std::vector<Sphere> &spheres, int &material) {
  expect(in, "{");
  expect(in, "numObjects");
  int count;
  in >> count;
  std::string token;
  for (int found = 0; found < count;) {
    in >> token;
    if (token == "MaterialIndex") { in >> material; }
    else if (token == "Sphere") {
      Sphere s;
      expect(in, "{"); expect(in, "center"); s.center = read_vec(in);
      expect(in, "radius"); in >> s.radius; expect(in, "}");
      s.material = material;
      spheres.push_back(s);
      found++;
    } else if (token == "Group") { read_group(in, spheres, material); found++; }
    else { std::fprintf(stderr, "unexpected %s\n", token.c_str()); std::exit(1); }
  }
  expect(in, "}");
}

static void write_tga(const char *path, int width, int height, const std::vector<unsigned char> &rgb) {
  FILE *file = std::fopen(path, "wb");
  if (!file) { std::perror(path); std::exit(1); }
  unsigned char header[18] = {0};
  header[2] = 2;
  header[12] = width & 255; header[13] = width >> 8;
  header[14] = height & 255; header[15] = height >> 8;
  header[16] = 24;
  std::fwrite(header, 1, 18, file);
  // TGA rows go bottom up, pixels as BGR, a byte at a time as the course's Image::SaveTGA does.
  for (int y = height - 1; y >= 0; y--) {
    for (int x = 0; x < width; x++) {
      const unsigned char *p = &rgb[3 * (y * width + x)];
      std::fputc(p[2], file); std::fputc(p[1], file); std::fputc(p[0], file);
    }
  }
  std::fclose(file);
}

int main(int argc, char **argv) {
  const char *input = nullptr, *output = nullptr, *depth_path = nullptr;
  int width = 100, height = 100;
  double depth_min = 0, depth_max = 1;
  for (int i = 1; i < argc; i++) {
    if (!std::strcmp(argv[i], "-input")) input = argv[++i];
    else if (!std::strcmp(argv[i], "-size")) { width = std::atoi(argv[++i]); height = std::atoi(argv[++i]); }
    else if (!std::strcmp(argv[i], "-output")) output = argv[++i];
    else if (!std::strcmp(argv[i], "-depth")) { depth_min = std::atof(argv[++i]); depth_max = std::atof(argv[++i]); depth_path = argv[++i]; }
    else { std::fprintf(stderr, "unknown flag %s\n", argv[i]); return 2; }
  }
  std::ifstream in(input);
  if (!in) { std::perror(input); return 1; }
  Vec3 center{0, 0, 0}, direction{0, 0, -1}, up{0, 1, 0}, background{0, 0, 0};
  double size = 1;
  std::vector<Vec3> materials;
  std::vector<Sphere> spheres;
  std::string token;
  while (in >> token) {
    if (token == "OrthographicCamera") {
      expect(in, "{"); expect(in, "center"); center = read_vec(in);
      expect(in, "direction"); direction = read_vec(in);
      expect(in, "up"); up = read_vec(in);
      expect(in, "size"); in >> size; expect(in, "}");
    } else if (token == "Background") {
      expect(in, "{"); expect(in, "color"); background = read_vec(in); expect(in, "}");
    } else if (token == "Materials") {
      expect(in, "{"); expect(in, "numMaterials");
      int count; in >> count;
      for (int i = 0; i < count; i++) {
        expect(in, "PhongMaterial"); expect(in, "{"); expect(in, "diffuseColor");
        materials.push_back(read_vec(in)); expect(in, "}");
      }
      expect(in, "}");
    } else if (token == "Group") {
      int material = -1;
      read_group(in, spheres, material);
    }
  }
  direction = normalized(direction);
  Vec3 horizontal = normalized(cross(direction, up));
  Vec3 screen_up = cross(horizontal, direction);
  std::vector<unsigned char> colour(3 * width * height), depth(3 * width * height);
  int side = width > height ? width : height;
  for (int y = 0; y < height; y++) {
    for (int x = 0; x < width; x++) {
      double u = ((x + 0.5) - 0.5 * width) / side * size;
      double v = ((0.5 * height) - (y + 0.5)) / side * size;
      Vec3 origin = add(center, add(mul(horizontal, u), mul(screen_up, v)));
      Hit hit{INFINITY, -1};
      for (const Sphere &s : spheres) intersect(s, origin, direction, -INFINITY, hit);
      unsigned char *c = &colour[3 * (y * width + x)];
      unsigned char *d = &depth[3 * (y * width + x)];
      Vec3 rgb = background;
      unsigned char grey = 0;
      if (hit.t < INFINITY) {
        rgb = hit.material >= 0 ? materials[hit.material] : Vec3{1, 1, 1};
        double g = (depth_max - hit.t) / (depth_max - depth_min);
        if (g < 0) g = 0;
        if (g > 1) g = 1;
        grey = (unsigned char)(g * 255);
      }
      c[0] = (unsigned char)(std::fmin(std::fmax(rgb.x, 0.0), 1.0) * 255);
      c[1] = (unsigned char)(std::fmin(std::fmax(rgb.y, 0.0), 1.0) * 255);
      c[2] = (unsigned char)(std::fmin(std::fmax(rgb.z, 0.0), 1.0) * 255);
      d[0] = d[1] = d[2] = grey;
    }
  }
  if (output) write_tga(output, width, height, colour);
  if (depth_path) write_tga(depth_path, width, height, depth);
  return 0;
}
