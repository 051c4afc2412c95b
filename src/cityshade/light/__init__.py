"""Light, not only shadow: sky directions, their visibility from receivers, the sky view factor,
the vertical sky component, and hourly weather files (docs/DESIGN.md §18).

Modules: :mod:`~cityshade.light.sky` (Tregenza, Reinhart and uniform skies, turned to grid
north), :mod:`~cityshade.light.visibility` (one packed bit per receiver and direction through
the exact engines), :mod:`~cityshade.light.metrics` (sky view factor, VSC, weights of patches
under a sky luminance), :mod:`~cityshade.light.weather` (EPW, TMY3, TMY2 through pvlib; sunny
hours), :mod:`~cityshade.light.sunlight` (probable sunlight hours of receivers from a weather
file, the sun traced at its exact position every hour).

Examples
--------
>>> from cityshade.light import sky_for_scene, sky_visibility, sky_view_factor
>>> sky = sky_for_scene(scene)                                           # doctest: +SKIP
>>> vis = sky_visibility(scene, points, normals, sky, t_days)            # doctest: +SKIP
>>> svf = sky_view_factor(vis)                                           # doctest: +SKIP
"""
from cityshade.light.metrics import (cie_overcast_luminance, patch_weights, sky_integral,
                                     sky_view_factor, uniform_luminance, vertical_sky_component)
from cityshade.light.sky import (DEFAULT_SKY, Sky, in_front, named_sky, reinhart_sky,
                                 sky_for_scene, tregenza_sky, uniform_sky)
from cityshade.light.sunlight import ProbableSunlight, probable_sunlight, weather_suns
from cityshade.light.visibility import (SkyVisibility, map_receivers, polygon_reference_points,
                                        sky_visibility)
from cityshade.light.weather import (SUNNY_DNI_W_M2, Weather, WeatherLocation, location_warning,
                                     read_weather, scene_location_warning)

__all__ = ["DEFAULT_SKY", "SUNNY_DNI_W_M2", "ProbableSunlight", "Sky", "SkyVisibility", "Weather",
           "WeatherLocation", "cie_overcast_luminance", "in_front", "location_warning",
           "map_receivers", "named_sky", "patch_weights", "polygon_reference_points",
           "probable_sunlight", "weather_suns",
           "read_weather", "reinhart_sky", "scene_location_warning", "sky_for_scene",
           "sky_integral", "sky_view_factor", "sky_visibility", "tregenza_sky",
           "uniform_luminance", "uniform_sky", "vertical_sky_component"]
