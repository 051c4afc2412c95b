<?xml version="1.0" encoding="UTF-8"?>
<!-- Synthetic city written by cityshade.samplegen (seed 7, 30 buildings, detail 0). Not real data. -->
<CityModel xmlns="http://www.opengis.net/citygml/2.0" xmlns:gml="http://www.opengis.net/gml" xmlns:xlink="http://www.w3.org/1999/xlink" xmlns:bldg="http://www.opengis.net/citygml/building/2.0" xmlns:dem="http://www.opengis.net/citygml/relief/2.0" xmlns:app="http://www.opengis.net/citygml/appearance/2.0" xmlns:gen="http://www.opengis.net/citygml/generics/2.0" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:schemaLocation="http://www.opengis.net/citygml/building/2.0 http://schemas.opengis.net/citygml/building/2.0/building.xsd http://www.opengis.net/citygml/relief/2.0 http://schemas.opengis.net/citygml/relief/2.0/relief.xsd http://www.opengis.net/citygml/appearance/2.0 http://schemas.opengis.net/citygml/appearance/2.0/appearance.xsd http://www.opengis.net/citygml/generics/2.0 http://schemas.opengis.net/citygml/generics/2.0/generics.xsd">
  <gml:name>cityshade sample city, seed 7</gml:name>
  <gml:boundedBy>
    <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
      <gml:lowerCorner>689980.000 5335980.000 515.000</gml:lowerCorner>
      <gml:upperCorner>690320.000 5336200.000 546.165</gml:upperCorner>
    </gml:Envelope>
  </gml:boundedBy>
  <cityObjectMember>
    <dem:ReliefFeature gml:id="SC_DEM">
      <gml:name>Terrain</gml:name>
      <dem:lod>2</dem:lod>
      <dem:reliefComponent>
        <dem:TINRelief gml:id="SC_DEM_tin">
          <dem:lod>2</dem:lod>
          <dem:tin>
            <gml:TriangulatedSurface gml:id="SC_DEM_surface">
              <gml:trianglePatches>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5335980.000 515.000 690000.000 5335980.000 515.353 690000.000 5336000.000 515.386 689980.000 5335980.000 515.000</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5335980.000 515.000 690000.000 5336000.000 515.386 689980.000 5336000.000 515.033 689980.000 5335980.000 515.000</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5335980.000 515.353 690020.000 5335980.000 515.706 690020.000 5336000.000 515.739 690000.000 5335980.000 515.353</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5335980.000 515.353 690020.000 5336000.000 515.739 690000.000 5336000.000 515.386 690000.000 5335980.000 515.353</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5335980.000 515.706 690040.000 5335980.000 516.059 690040.000 5336000.000 516.092 690020.000 5335980.000 515.706</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5335980.000 515.706 690040.000 5336000.000 516.092 690020.000 5336000.000 515.739 690020.000 5335980.000 515.706</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5335980.000 516.059 690060.000 5335980.000 516.412 690060.000 5336000.000 516.445 690040.000 5335980.000 516.059</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5335980.000 516.059 690060.000 5336000.000 516.445 690040.000 5336000.000 516.092 690040.000 5335980.000 516.059</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5335980.000 516.412 690080.000 5335980.000 516.765 690080.000 5336000.000 516.798 690060.000 5335980.000 516.412</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5335980.000 516.412 690080.000 5336000.000 516.798 690060.000 5336000.000 516.445 690060.000 5335980.000 516.412</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5335980.000 516.765 690100.000 5335980.000 517.118 690100.000 5336000.000 517.151 690080.000 5335980.000 516.765</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5335980.000 516.765 690100.000 5336000.000 517.151 690080.000 5336000.000 516.798 690080.000 5335980.000 516.765</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5335980.000 517.118 690120.000 5335980.000 517.471 690120.000 5336000.000 517.504 690100.000 5335980.000 517.118</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5335980.000 517.118 690120.000 5336000.000 517.504 690100.000 5336000.000 517.151 690100.000 5335980.000 517.118</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5335980.000 517.471 690140.000 5335980.000 517.824 690140.000 5336000.000 517.857 690120.000 5335980.000 517.471</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5335980.000 517.471 690140.000 5336000.000 517.857 690120.000 5336000.000 517.504 690120.000 5335980.000 517.471</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5335980.000 517.824 690160.000 5335980.000 518.176 690160.000 5336000.000 518.210 690140.000 5335980.000 517.824</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5335980.000 517.824 690160.000 5336000.000 518.210 690140.000 5336000.000 517.857 690140.000 5335980.000 517.824</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5335980.000 518.176 690180.000 5335980.000 518.529 690180.000 5336000.000 518.562 690160.000 5335980.000 518.176</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5335980.000 518.176 690180.000 5336000.000 518.562 690160.000 5336000.000 518.210 690160.000 5335980.000 518.176</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5335980.000 518.529 690200.000 5335980.000 518.882 690200.000 5336000.000 518.915 690180.000 5335980.000 518.529</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5335980.000 518.529 690200.000 5336000.000 518.915 690180.000 5336000.000 518.562 690180.000 5335980.000 518.529</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5335980.000 518.882 690220.000 5335980.000 519.235 690220.000 5336000.000 519.268 690200.000 5335980.000 518.882</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5335980.000 518.882 690220.000 5336000.000 519.268 690200.000 5336000.000 518.915 690200.000 5335980.000 518.882</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5335980.000 519.235 690240.000 5335980.000 519.588 690240.000 5336000.000 519.621 690220.000 5335980.000 519.235</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5335980.000 519.235 690240.000 5336000.000 519.621 690220.000 5336000.000 519.268 690220.000 5335980.000 519.235</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5335980.000 519.588 690260.000 5335980.000 519.941 690260.000 5336000.000 519.974 690240.000 5335980.000 519.588</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5335980.000 519.588 690260.000 5336000.000 519.974 690240.000 5336000.000 519.621 690240.000 5335980.000 519.588</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5335980.000 519.941 690280.000 5335980.000 520.294 690280.000 5336000.000 520.327 690260.000 5335980.000 519.941</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5335980.000 519.941 690280.000 5336000.000 520.327 690260.000 5336000.000 519.974 690260.000 5335980.000 519.941</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5335980.000 520.294 690300.000 5335980.000 520.647 690300.000 5336000.000 520.680 690280.000 5335980.000 520.294</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5335980.000 520.294 690300.000 5336000.000 520.680 690280.000 5336000.000 520.327 690280.000 5335980.000 520.294</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5335980.000 520.647 690320.000 5335980.000 521.000 690320.000 5336000.000 521.033 690300.000 5335980.000 520.647</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5335980.000 520.647 690320.000 5336000.000 521.033 690300.000 5336000.000 520.680 690300.000 5335980.000 520.647</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336000.000 515.033 690000.000 5336000.000 515.386 690000.000 5336020.000 515.485 689980.000 5336000.000 515.033</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336000.000 515.033 690000.000 5336020.000 515.485 689980.000 5336020.000 515.132 689980.000 5336000.000 515.033</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336000.000 515.386 690020.000 5336000.000 515.739 690020.000 5336020.000 515.838 690000.000 5336000.000 515.386</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336000.000 515.386 690020.000 5336020.000 515.838 690000.000 5336020.000 515.485 690000.000 5336000.000 515.386</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336000.000 515.739 690040.000 5336000.000 516.092 690040.000 5336020.000 516.191 690020.000 5336000.000 515.739</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336000.000 515.739 690040.000 5336020.000 516.191 690020.000 5336020.000 515.838 690020.000 5336000.000 515.739</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336000.000 516.092 690060.000 5336000.000 516.445 690060.000 5336020.000 516.544 690040.000 5336000.000 516.092</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336000.000 516.092 690060.000 5336020.000 516.544 690040.000 5336020.000 516.191 690040.000 5336000.000 516.092</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336000.000 516.445 690080.000 5336000.000 516.798 690080.000 5336020.000 516.897 690060.000 5336000.000 516.445</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336000.000 516.445 690080.000 5336020.000 516.897 690060.000 5336020.000 516.544 690060.000 5336000.000 516.445</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336000.000 516.798 690100.000 5336000.000 517.151 690100.000 5336020.000 517.250 690080.000 5336000.000 516.798</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336000.000 516.798 690100.000 5336020.000 517.250 690080.000 5336020.000 516.897 690080.000 5336000.000 516.798</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336000.000 517.151 690120.000 5336000.000 517.504 690120.000 5336020.000 517.603 690100.000 5336000.000 517.151</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336000.000 517.151 690120.000 5336020.000 517.603 690100.000 5336020.000 517.250 690100.000 5336000.000 517.151</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336000.000 517.504 690140.000 5336000.000 517.857 690140.000 5336020.000 517.956 690120.000 5336000.000 517.504</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336000.000 517.504 690140.000 5336020.000 517.956 690120.000 5336020.000 517.603 690120.000 5336000.000 517.504</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336000.000 517.857 690160.000 5336000.000 518.210 690160.000 5336020.000 518.309 690140.000 5336000.000 517.857</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336000.000 517.857 690160.000 5336020.000 518.309 690140.000 5336020.000 517.956 690140.000 5336000.000 517.857</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336000.000 518.210 690180.000 5336000.000 518.562 690180.000 5336020.000 518.662 690160.000 5336000.000 518.210</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336000.000 518.210 690180.000 5336020.000 518.662 690160.000 5336020.000 518.309 690160.000 5336000.000 518.210</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336000.000 518.562 690200.000 5336000.000 518.915 690200.000 5336020.000 519.015 690180.000 5336000.000 518.562</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336000.000 518.562 690200.000 5336020.000 519.015 690180.000 5336020.000 518.662 690180.000 5336000.000 518.562</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336000.000 518.915 690220.000 5336000.000 519.268 690220.000 5336020.000 519.368 690200.000 5336000.000 518.915</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336000.000 518.915 690220.000 5336020.000 519.368 690200.000 5336020.000 519.015 690200.000 5336000.000 518.915</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336000.000 519.268 690240.000 5336000.000 519.621 690240.000 5336020.000 519.720 690220.000 5336000.000 519.268</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336000.000 519.268 690240.000 5336020.000 519.720 690220.000 5336020.000 519.368 690220.000 5336000.000 519.268</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336000.000 519.621 690260.000 5336000.000 519.974 690260.000 5336020.000 520.073 690240.000 5336000.000 519.621</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336000.000 519.621 690260.000 5336020.000 520.073 690240.000 5336020.000 519.720 690240.000 5336000.000 519.621</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336000.000 519.974 690280.000 5336000.000 520.327 690280.000 5336020.000 520.426 690260.000 5336000.000 519.974</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336000.000 519.974 690280.000 5336020.000 520.426 690260.000 5336020.000 520.073 690260.000 5336000.000 519.974</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336000.000 520.327 690300.000 5336000.000 520.680 690300.000 5336020.000 520.779 690280.000 5336000.000 520.327</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336000.000 520.327 690300.000 5336020.000 520.779 690280.000 5336020.000 520.426 690280.000 5336000.000 520.327</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336000.000 520.680 690320.000 5336000.000 521.033 690320.000 5336020.000 521.132 690300.000 5336000.000 520.680</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336000.000 520.680 690320.000 5336020.000 521.132 690300.000 5336020.000 520.779 690300.000 5336000.000 520.680</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336020.000 515.132 690000.000 5336020.000 515.485 690000.000 5336040.000 515.650 689980.000 5336020.000 515.132</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336020.000 515.132 690000.000 5336040.000 515.650 689980.000 5336040.000 515.298 689980.000 5336020.000 515.132</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336020.000 515.485 690020.000 5336020.000 515.838 690020.000 5336040.000 516.003 690000.000 5336020.000 515.485</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336020.000 515.485 690020.000 5336040.000 516.003 690000.000 5336040.000 515.650 690000.000 5336020.000 515.485</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336020.000 515.838 690040.000 5336020.000 516.191 690040.000 5336040.000 516.356 690020.000 5336020.000 515.838</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336020.000 515.838 690040.000 5336040.000 516.356 690020.000 5336040.000 516.003 690020.000 5336020.000 515.838</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336020.000 516.191 690060.000 5336020.000 516.544 690060.000 5336040.000 516.709 690040.000 5336020.000 516.191</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336020.000 516.191 690060.000 5336040.000 516.709 690040.000 5336040.000 516.356 690040.000 5336020.000 516.191</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336020.000 516.544 690080.000 5336020.000 516.897 690080.000 5336040.000 517.062 690060.000 5336020.000 516.544</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336020.000 516.544 690080.000 5336040.000 517.062 690060.000 5336040.000 516.709 690060.000 5336020.000 516.544</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336020.000 516.897 690100.000 5336020.000 517.250 690100.000 5336040.000 517.415 690080.000 5336020.000 516.897</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336020.000 516.897 690100.000 5336040.000 517.415 690080.000 5336040.000 517.062 690080.000 5336020.000 516.897</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336020.000 517.250 690120.000 5336020.000 517.603 690120.000 5336040.000 517.768 690100.000 5336020.000 517.250</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336020.000 517.250 690120.000 5336040.000 517.768 690100.000 5336040.000 517.415 690100.000 5336020.000 517.250</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336020.000 517.603 690140.000 5336020.000 517.956 690140.000 5336040.000 518.121 690120.000 5336020.000 517.603</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336020.000 517.603 690140.000 5336040.000 518.121 690120.000 5336040.000 517.768 690120.000 5336020.000 517.603</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336020.000 517.956 690160.000 5336020.000 518.309 690160.000 5336040.000 518.474 690140.000 5336020.000 517.956</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336020.000 517.956 690160.000 5336040.000 518.474 690140.000 5336040.000 518.121 690140.000 5336020.000 517.956</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336020.000 518.309 690180.000 5336020.000 518.662 690180.000 5336040.000 518.827 690160.000 5336020.000 518.309</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336020.000 518.309 690180.000 5336040.000 518.827 690160.000 5336040.000 518.474 690160.000 5336020.000 518.309</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336020.000 518.662 690200.000 5336020.000 519.015 690200.000 5336040.000 519.180 690180.000 5336020.000 518.662</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336020.000 518.662 690200.000 5336040.000 519.180 690180.000 5336040.000 518.827 690180.000 5336020.000 518.662</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336020.000 519.015 690220.000 5336020.000 519.368 690220.000 5336040.000 519.533 690200.000 5336020.000 519.015</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336020.000 519.015 690220.000 5336040.000 519.533 690200.000 5336040.000 519.180 690200.000 5336020.000 519.015</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336020.000 519.368 690240.000 5336020.000 519.720 690240.000 5336040.000 519.886 690220.000 5336020.000 519.368</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336020.000 519.368 690240.000 5336040.000 519.886 690220.000 5336040.000 519.533 690220.000 5336020.000 519.368</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336020.000 519.720 690260.000 5336020.000 520.073 690260.000 5336040.000 520.239 690240.000 5336020.000 519.720</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336020.000 519.720 690260.000 5336040.000 520.239 690240.000 5336040.000 519.886 690240.000 5336020.000 519.720</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336020.000 520.073 690280.000 5336020.000 520.426 690280.000 5336040.000 520.592 690260.000 5336020.000 520.073</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336020.000 520.073 690280.000 5336040.000 520.592 690260.000 5336040.000 520.239 690260.000 5336020.000 520.073</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336020.000 520.426 690300.000 5336020.000 520.779 690300.000 5336040.000 520.945 690280.000 5336020.000 520.426</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336020.000 520.426 690300.000 5336040.000 520.945 690280.000 5336040.000 520.592 690280.000 5336020.000 520.426</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336020.000 520.779 690320.000 5336020.000 521.132 690320.000 5336040.000 521.298 690300.000 5336020.000 520.779</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336020.000 520.779 690320.000 5336040.000 521.298 690300.000 5336040.000 520.945 690300.000 5336020.000 520.779</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336040.000 515.298 690000.000 5336040.000 515.650 690000.000 5336060.000 515.882 689980.000 5336040.000 515.298</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336040.000 515.298 690000.000 5336060.000 515.882 689980.000 5336060.000 515.529 689980.000 5336040.000 515.298</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336040.000 515.650 690020.000 5336040.000 516.003 690020.000 5336060.000 516.235 690000.000 5336040.000 515.650</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336040.000 515.650 690020.000 5336060.000 516.235 690000.000 5336060.000 515.882 690000.000 5336040.000 515.650</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336040.000 516.003 690040.000 5336040.000 516.356 690040.000 5336060.000 516.588 690020.000 5336040.000 516.003</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336040.000 516.003 690040.000 5336060.000 516.588 690020.000 5336060.000 516.235 690020.000 5336040.000 516.003</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336040.000 516.356 690060.000 5336040.000 516.709 690060.000 5336060.000 516.941 690040.000 5336040.000 516.356</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336040.000 516.356 690060.000 5336060.000 516.941 690040.000 5336060.000 516.588 690040.000 5336040.000 516.356</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336040.000 516.709 690080.000 5336040.000 517.062 690080.000 5336060.000 517.294 690060.000 5336040.000 516.709</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336040.000 516.709 690080.000 5336060.000 517.294 690060.000 5336060.000 516.941 690060.000 5336040.000 516.709</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336040.000 517.062 690100.000 5336040.000 517.415 690100.000 5336060.000 517.647 690080.000 5336040.000 517.062</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336040.000 517.062 690100.000 5336060.000 517.647 690080.000 5336060.000 517.294 690080.000 5336040.000 517.062</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336040.000 517.415 690120.000 5336040.000 517.768 690120.000 5336060.000 518.000 690100.000 5336040.000 517.415</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336040.000 517.415 690120.000 5336060.000 518.000 690100.000 5336060.000 517.647 690100.000 5336040.000 517.415</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336040.000 517.768 690140.000 5336040.000 518.121 690140.000 5336060.000 518.352 690120.000 5336040.000 517.768</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336040.000 517.768 690140.000 5336060.000 518.352 690120.000 5336060.000 518.000 690120.000 5336040.000 517.768</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336040.000 518.121 690160.000 5336040.000 518.474 690160.000 5336060.000 518.705 690140.000 5336040.000 518.121</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336040.000 518.121 690160.000 5336060.000 518.705 690140.000 5336060.000 518.352 690140.000 5336040.000 518.121</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336040.000 518.474 690180.000 5336040.000 518.827 690180.000 5336060.000 519.058 690160.000 5336040.000 518.474</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336040.000 518.474 690180.000 5336060.000 519.058 690160.000 5336060.000 518.705 690160.000 5336040.000 518.474</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336040.000 518.827 690200.000 5336040.000 519.180 690200.000 5336060.000 519.411 690180.000 5336040.000 518.827</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336040.000 518.827 690200.000 5336060.000 519.411 690180.000 5336060.000 519.058 690180.000 5336040.000 518.827</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336040.000 519.180 690220.000 5336040.000 519.533 690220.000 5336060.000 519.764 690200.000 5336040.000 519.180</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336040.000 519.180 690220.000 5336060.000 519.764 690200.000 5336060.000 519.411 690200.000 5336040.000 519.180</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336040.000 519.533 690240.000 5336040.000 519.886 690240.000 5336060.000 520.117 690220.000 5336040.000 519.533</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336040.000 519.533 690240.000 5336060.000 520.117 690220.000 5336060.000 519.764 690220.000 5336040.000 519.533</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336040.000 519.886 690260.000 5336040.000 520.239 690260.000 5336060.000 520.470 690240.000 5336040.000 519.886</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336040.000 519.886 690260.000 5336060.000 520.470 690240.000 5336060.000 520.117 690240.000 5336040.000 519.886</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336040.000 520.239 690280.000 5336040.000 520.592 690280.000 5336060.000 520.823 690260.000 5336040.000 520.239</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336040.000 520.239 690280.000 5336060.000 520.823 690260.000 5336060.000 520.470 690260.000 5336040.000 520.239</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336040.000 520.592 690300.000 5336040.000 520.945 690300.000 5336060.000 521.176 690280.000 5336040.000 520.592</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336040.000 520.592 690300.000 5336060.000 521.176 690280.000 5336060.000 520.823 690280.000 5336040.000 520.592</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336040.000 520.945 690320.000 5336040.000 521.298 690320.000 5336060.000 521.529 690300.000 5336040.000 520.945</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336040.000 520.945 690320.000 5336060.000 521.529 690300.000 5336060.000 521.176 690300.000 5336040.000 520.945</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336060.000 515.529 690000.000 5336060.000 515.882 690000.000 5336080.000 516.179 689980.000 5336060.000 515.529</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336060.000 515.529 690000.000 5336080.000 516.179 689980.000 5336080.000 515.826 689980.000 5336060.000 515.529</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336060.000 515.882 690020.000 5336060.000 516.235 690020.000 5336080.000 516.532 690000.000 5336060.000 515.882</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336060.000 515.882 690020.000 5336080.000 516.532 690000.000 5336080.000 516.179 690000.000 5336060.000 515.882</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336060.000 516.235 690040.000 5336060.000 516.588 690040.000 5336080.000 516.885 690020.000 5336060.000 516.235</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336060.000 516.235 690040.000 5336080.000 516.885 690020.000 5336080.000 516.532 690020.000 5336060.000 516.235</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336060.000 516.588 690060.000 5336060.000 516.941 690060.000 5336080.000 517.238 690040.000 5336060.000 516.588</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336060.000 516.588 690060.000 5336080.000 517.238 690040.000 5336080.000 516.885 690040.000 5336060.000 516.588</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336060.000 516.941 690080.000 5336060.000 517.294 690080.000 5336080.000 517.591 690060.000 5336060.000 516.941</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336060.000 516.941 690080.000 5336080.000 517.591 690060.000 5336080.000 517.238 690060.000 5336060.000 516.941</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336060.000 517.294 690100.000 5336060.000 517.647 690100.000 5336080.000 517.944 690080.000 5336060.000 517.294</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336060.000 517.294 690100.000 5336080.000 517.944 690080.000 5336080.000 517.591 690080.000 5336060.000 517.294</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336060.000 517.647 690120.000 5336060.000 518.000 690120.000 5336080.000 518.297 690100.000 5336060.000 517.647</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336060.000 517.647 690120.000 5336080.000 518.297 690100.000 5336080.000 517.944 690100.000 5336060.000 517.647</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336060.000 518.000 690140.000 5336060.000 518.352 690140.000 5336080.000 518.650 690120.000 5336060.000 518.000</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336060.000 518.000 690140.000 5336080.000 518.650 690120.000 5336080.000 518.297 690120.000 5336060.000 518.000</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336060.000 518.352 690160.000 5336060.000 518.705 690160.000 5336080.000 519.003 690140.000 5336060.000 518.352</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336060.000 518.352 690160.000 5336080.000 519.003 690140.000 5336080.000 518.650 690140.000 5336060.000 518.352</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336060.000 518.705 690180.000 5336060.000 519.058 690180.000 5336080.000 519.356 690160.000 5336060.000 518.705</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336060.000 518.705 690180.000 5336080.000 519.356 690160.000 5336080.000 519.003 690160.000 5336060.000 518.705</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336060.000 519.058 690200.000 5336060.000 519.411 690200.000 5336080.000 519.709 690180.000 5336060.000 519.058</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336060.000 519.058 690200.000 5336080.000 519.709 690180.000 5336080.000 519.356 690180.000 5336060.000 519.058</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336060.000 519.411 690220.000 5336060.000 519.764 690220.000 5336080.000 520.062 690200.000 5336060.000 519.411</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336060.000 519.411 690220.000 5336080.000 520.062 690200.000 5336080.000 519.709 690200.000 5336060.000 519.411</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336060.000 519.764 690240.000 5336060.000 520.117 690240.000 5336080.000 520.415 690220.000 5336060.000 519.764</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336060.000 519.764 690240.000 5336080.000 520.415 690220.000 5336080.000 520.062 690220.000 5336060.000 519.764</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336060.000 520.117 690260.000 5336060.000 520.470 690260.000 5336080.000 520.768 690240.000 5336060.000 520.117</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336060.000 520.117 690260.000 5336080.000 520.768 690240.000 5336080.000 520.415 690240.000 5336060.000 520.117</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336060.000 520.470 690280.000 5336060.000 520.823 690280.000 5336080.000 521.121 690260.000 5336060.000 520.470</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336060.000 520.470 690280.000 5336080.000 521.121 690260.000 5336080.000 520.768 690260.000 5336060.000 520.470</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336060.000 520.823 690300.000 5336060.000 521.176 690300.000 5336080.000 521.474 690280.000 5336060.000 520.823</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336060.000 520.823 690300.000 5336080.000 521.474 690280.000 5336080.000 521.121 690280.000 5336060.000 520.823</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336060.000 521.176 690320.000 5336060.000 521.529 690320.000 5336080.000 521.826 690300.000 5336060.000 521.176</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336060.000 521.176 690320.000 5336080.000 521.826 690300.000 5336080.000 521.474 690300.000 5336060.000 521.176</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336080.000 515.826 690000.000 5336080.000 516.179 690000.000 5336100.000 516.543 689980.000 5336080.000 515.826</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336080.000 515.826 690000.000 5336100.000 516.543 689980.000 5336100.000 516.190 689980.000 5336080.000 515.826</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336080.000 516.179 690020.000 5336080.000 516.532 690020.000 5336100.000 516.896 690000.000 5336080.000 516.179</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336080.000 516.179 690020.000 5336100.000 516.896 690000.000 5336100.000 516.543 690000.000 5336080.000 516.179</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336080.000 516.532 690040.000 5336080.000 516.885 690040.000 5336100.000 517.249 690020.000 5336080.000 516.532</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336080.000 516.532 690040.000 5336100.000 517.249 690020.000 5336100.000 516.896 690020.000 5336080.000 516.532</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336080.000 516.885 690060.000 5336080.000 517.238 690060.000 5336100.000 517.602 690040.000 5336080.000 516.885</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336080.000 516.885 690060.000 5336100.000 517.602 690040.000 5336100.000 517.249 690040.000 5336080.000 516.885</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336080.000 517.238 690080.000 5336080.000 517.591 690080.000 5336100.000 517.955 690060.000 5336080.000 517.238</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336080.000 517.238 690080.000 5336100.000 517.955 690060.000 5336100.000 517.602 690060.000 5336080.000 517.238</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336080.000 517.591 690100.000 5336080.000 517.944 690100.000 5336100.000 518.308 690080.000 5336080.000 517.591</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336080.000 517.591 690100.000 5336100.000 518.308 690080.000 5336100.000 517.955 690080.000 5336080.000 517.591</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336080.000 517.944 690120.000 5336080.000 518.297 690120.000 5336100.000 518.661 690100.000 5336080.000 517.944</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336080.000 517.944 690120.000 5336100.000 518.661 690100.000 5336100.000 518.308 690100.000 5336080.000 517.944</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336080.000 518.297 690140.000 5336080.000 518.650 690140.000 5336100.000 519.014 690120.000 5336080.000 518.297</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336080.000 518.297 690140.000 5336100.000 519.014 690120.000 5336100.000 518.661 690120.000 5336080.000 518.297</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336080.000 518.650 690160.000 5336080.000 519.003 690160.000 5336100.000 519.367 690140.000 5336080.000 518.650</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336080.000 518.650 690160.000 5336100.000 519.367 690140.000 5336100.000 519.014 690140.000 5336080.000 518.650</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336080.000 519.003 690180.000 5336080.000 519.356 690180.000 5336100.000 519.719 690160.000 5336080.000 519.003</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336080.000 519.003 690180.000 5336100.000 519.719 690160.000 5336100.000 519.367 690160.000 5336080.000 519.003</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336080.000 519.356 690200.000 5336080.000 519.709 690200.000 5336100.000 520.072 690180.000 5336080.000 519.356</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336080.000 519.356 690200.000 5336100.000 520.072 690180.000 5336100.000 519.719 690180.000 5336080.000 519.356</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336080.000 519.709 690220.000 5336080.000 520.062 690220.000 5336100.000 520.425 690200.000 5336080.000 519.709</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336080.000 519.709 690220.000 5336100.000 520.425 690200.000 5336100.000 520.072 690200.000 5336080.000 519.709</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336080.000 520.062 690240.000 5336080.000 520.415 690240.000 5336100.000 520.778 690220.000 5336080.000 520.062</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336080.000 520.062 690240.000 5336100.000 520.778 690220.000 5336100.000 520.425 690220.000 5336080.000 520.062</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336080.000 520.415 690260.000 5336080.000 520.768 690260.000 5336100.000 521.131 690240.000 5336080.000 520.415</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336080.000 520.415 690260.000 5336100.000 521.131 690240.000 5336100.000 520.778 690240.000 5336080.000 520.415</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336080.000 520.768 690280.000 5336080.000 521.121 690280.000 5336100.000 521.484 690260.000 5336080.000 520.768</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336080.000 520.768 690280.000 5336100.000 521.484 690260.000 5336100.000 521.131 690260.000 5336080.000 520.768</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336080.000 521.121 690300.000 5336080.000 521.474 690300.000 5336100.000 521.837 690280.000 5336080.000 521.121</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336080.000 521.121 690300.000 5336100.000 521.837 690280.000 5336100.000 521.484 690280.000 5336080.000 521.121</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336080.000 521.474 690320.000 5336080.000 521.826 690320.000 5336100.000 522.190 690300.000 5336080.000 521.474</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336080.000 521.474 690320.000 5336100.000 522.190 690300.000 5336100.000 521.837 690300.000 5336080.000 521.474</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336100.000 516.190 690000.000 5336100.000 516.543 690000.000 5336120.000 516.973 689980.000 5336100.000 516.190</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336100.000 516.190 690000.000 5336120.000 516.973 689980.000 5336120.000 516.620 689980.000 5336100.000 516.190</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336100.000 516.543 690020.000 5336100.000 516.896 690020.000 5336120.000 517.326 690000.000 5336100.000 516.543</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336100.000 516.543 690020.000 5336120.000 517.326 690000.000 5336120.000 516.973 690000.000 5336100.000 516.543</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336100.000 516.896 690040.000 5336100.000 517.249 690040.000 5336120.000 517.679 690020.000 5336100.000 516.896</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336100.000 516.896 690040.000 5336120.000 517.679 690020.000 5336120.000 517.326 690020.000 5336100.000 516.896</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336100.000 517.249 690060.000 5336100.000 517.602 690060.000 5336120.000 518.032 690040.000 5336100.000 517.249</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336100.000 517.249 690060.000 5336120.000 518.032 690040.000 5336120.000 517.679 690040.000 5336100.000 517.249</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336100.000 517.602 690080.000 5336100.000 517.955 690080.000 5336120.000 518.385 690060.000 5336100.000 517.602</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336100.000 517.602 690080.000 5336120.000 518.385 690060.000 5336120.000 518.032 690060.000 5336100.000 517.602</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336100.000 517.955 690100.000 5336100.000 518.308 690100.000 5336120.000 518.737 690080.000 5336100.000 517.955</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336100.000 517.955 690100.000 5336120.000 518.737 690080.000 5336120.000 518.385 690080.000 5336100.000 517.955</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336100.000 518.308 690120.000 5336100.000 518.661 690120.000 5336120.000 519.090 690100.000 5336100.000 518.308</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336100.000 518.308 690120.000 5336120.000 519.090 690100.000 5336120.000 518.737 690100.000 5336100.000 518.308</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336100.000 518.661 690140.000 5336100.000 519.014 690140.000 5336120.000 519.443 690120.000 5336100.000 518.661</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336100.000 518.661 690140.000 5336120.000 519.443 690120.000 5336120.000 519.090 690120.000 5336100.000 518.661</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336100.000 519.014 690160.000 5336100.000 519.367 690160.000 5336120.000 519.796 690140.000 5336100.000 519.014</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336100.000 519.014 690160.000 5336120.000 519.796 690140.000 5336120.000 519.443 690140.000 5336100.000 519.014</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336100.000 519.367 690180.000 5336100.000 519.719 690180.000 5336120.000 520.149 690160.000 5336100.000 519.367</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336100.000 519.367 690180.000 5336120.000 520.149 690160.000 5336120.000 519.796 690160.000 5336100.000 519.367</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336100.000 519.719 690200.000 5336100.000 520.072 690200.000 5336120.000 520.502 690180.000 5336100.000 519.719</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336100.000 519.719 690200.000 5336120.000 520.502 690180.000 5336120.000 520.149 690180.000 5336100.000 519.719</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336100.000 520.072 690220.000 5336100.000 520.425 690220.000 5336120.000 520.855 690200.000 5336100.000 520.072</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336100.000 520.072 690220.000 5336120.000 520.855 690200.000 5336120.000 520.502 690200.000 5336100.000 520.072</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336100.000 520.425 690240.000 5336100.000 520.778 690240.000 5336120.000 521.208 690220.000 5336100.000 520.425</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336100.000 520.425 690240.000 5336120.000 521.208 690220.000 5336120.000 520.855 690220.000 5336100.000 520.425</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336100.000 520.778 690260.000 5336100.000 521.131 690260.000 5336120.000 521.561 690240.000 5336100.000 520.778</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336100.000 520.778 690260.000 5336120.000 521.561 690240.000 5336120.000 521.208 690240.000 5336100.000 520.778</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336100.000 521.131 690280.000 5336100.000 521.484 690280.000 5336120.000 521.914 690260.000 5336100.000 521.131</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336100.000 521.131 690280.000 5336120.000 521.914 690260.000 5336120.000 521.561 690260.000 5336100.000 521.131</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336100.000 521.484 690300.000 5336100.000 521.837 690300.000 5336120.000 522.267 690280.000 5336100.000 521.484</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336100.000 521.484 690300.000 5336120.000 522.267 690280.000 5336120.000 521.914 690280.000 5336100.000 521.484</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336100.000 521.837 690320.000 5336100.000 522.190 690320.000 5336120.000 522.620 690300.000 5336100.000 521.837</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336100.000 521.837 690320.000 5336120.000 522.620 690300.000 5336120.000 522.267 690300.000 5336100.000 521.837</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336120.000 516.620 690000.000 5336120.000 516.973 690000.000 5336140.000 517.469 689980.000 5336120.000 516.620</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336120.000 516.620 690000.000 5336140.000 517.469 689980.000 5336140.000 517.116 689980.000 5336120.000 516.620</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336120.000 516.973 690020.000 5336120.000 517.326 690020.000 5336140.000 517.822 690000.000 5336120.000 516.973</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336120.000 516.973 690020.000 5336140.000 517.822 690000.000 5336140.000 517.469 690000.000 5336120.000 516.973</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336120.000 517.326 690040.000 5336120.000 517.679 690040.000 5336140.000 518.175 690020.000 5336120.000 517.326</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336120.000 517.326 690040.000 5336140.000 518.175 690020.000 5336140.000 517.822 690020.000 5336120.000 517.326</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336120.000 517.679 690060.000 5336120.000 518.032 690060.000 5336140.000 518.527 690040.000 5336120.000 517.679</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336120.000 517.679 690060.000 5336140.000 518.527 690040.000 5336140.000 518.175 690040.000 5336120.000 517.679</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336120.000 518.032 690080.000 5336120.000 518.385 690080.000 5336140.000 518.880 690060.000 5336120.000 518.032</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336120.000 518.032 690080.000 5336140.000 518.880 690060.000 5336140.000 518.527 690060.000 5336120.000 518.032</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336120.000 518.385 690100.000 5336120.000 518.737 690100.000 5336140.000 519.233 690080.000 5336120.000 518.385</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336120.000 518.385 690100.000 5336140.000 519.233 690080.000 5336140.000 518.880 690080.000 5336120.000 518.385</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336120.000 518.737 690120.000 5336120.000 519.090 690120.000 5336140.000 519.586 690100.000 5336120.000 518.737</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336120.000 518.737 690120.000 5336140.000 519.586 690100.000 5336140.000 519.233 690100.000 5336120.000 518.737</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336120.000 519.090 690140.000 5336120.000 519.443 690140.000 5336140.000 519.939 690120.000 5336120.000 519.090</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336120.000 519.090 690140.000 5336140.000 519.939 690120.000 5336140.000 519.586 690120.000 5336120.000 519.090</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336120.000 519.443 690160.000 5336120.000 519.796 690160.000 5336140.000 520.292 690140.000 5336120.000 519.443</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336120.000 519.443 690160.000 5336140.000 520.292 690140.000 5336140.000 519.939 690140.000 5336120.000 519.443</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336120.000 519.796 690180.000 5336120.000 520.149 690180.000 5336140.000 520.645 690160.000 5336120.000 519.796</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336120.000 519.796 690180.000 5336140.000 520.645 690160.000 5336140.000 520.292 690160.000 5336120.000 519.796</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336120.000 520.149 690200.000 5336120.000 520.502 690200.000 5336140.000 520.998 690180.000 5336120.000 520.149</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336120.000 520.149 690200.000 5336140.000 520.998 690180.000 5336140.000 520.645 690180.000 5336120.000 520.149</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336120.000 520.502 690220.000 5336120.000 520.855 690220.000 5336140.000 521.351 690200.000 5336120.000 520.502</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336120.000 520.502 690220.000 5336140.000 521.351 690200.000 5336140.000 520.998 690200.000 5336120.000 520.502</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336120.000 520.855 690240.000 5336120.000 521.208 690240.000 5336140.000 521.704 690220.000 5336120.000 520.855</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336120.000 520.855 690240.000 5336140.000 521.704 690220.000 5336140.000 521.351 690220.000 5336120.000 520.855</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336120.000 521.208 690260.000 5336120.000 521.561 690260.000 5336140.000 522.057 690240.000 5336120.000 521.208</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336120.000 521.208 690260.000 5336140.000 522.057 690240.000 5336140.000 521.704 690240.000 5336120.000 521.208</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336120.000 521.561 690280.000 5336120.000 521.914 690280.000 5336140.000 522.410 690260.000 5336120.000 521.561</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336120.000 521.561 690280.000 5336140.000 522.410 690260.000 5336140.000 522.057 690260.000 5336120.000 521.561</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336120.000 521.914 690300.000 5336120.000 522.267 690300.000 5336140.000 522.763 690280.000 5336120.000 521.914</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336120.000 521.914 690300.000 5336140.000 522.763 690280.000 5336140.000 522.410 690280.000 5336120.000 521.914</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336120.000 522.267 690320.000 5336120.000 522.620 690320.000 5336140.000 523.116 690300.000 5336120.000 522.267</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336120.000 522.267 690320.000 5336140.000 523.116 690300.000 5336140.000 522.763 690300.000 5336120.000 522.267</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336140.000 517.116 690000.000 5336140.000 517.469 690000.000 5336160.000 518.031 689980.000 5336140.000 517.116</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336140.000 517.116 690000.000 5336160.000 518.031 689980.000 5336160.000 517.678 689980.000 5336140.000 517.116</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336140.000 517.469 690020.000 5336140.000 517.822 690020.000 5336160.000 518.384 690000.000 5336140.000 517.469</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336140.000 517.469 690020.000 5336160.000 518.384 690000.000 5336160.000 518.031 690000.000 5336140.000 517.469</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336140.000 517.822 690040.000 5336140.000 518.175 690040.000 5336160.000 518.737 690020.000 5336140.000 517.822</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336140.000 517.822 690040.000 5336160.000 518.737 690020.000 5336160.000 518.384 690020.000 5336140.000 517.822</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336140.000 518.175 690060.000 5336140.000 518.527 690060.000 5336160.000 519.089 690040.000 5336140.000 518.175</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336140.000 518.175 690060.000 5336160.000 519.089 690040.000 5336160.000 518.737 690040.000 5336140.000 518.175</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336140.000 518.527 690080.000 5336140.000 518.880 690080.000 5336160.000 519.442 690060.000 5336140.000 518.527</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336140.000 518.527 690080.000 5336160.000 519.442 690060.000 5336160.000 519.089 690060.000 5336140.000 518.527</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336140.000 518.880 690100.000 5336140.000 519.233 690100.000 5336160.000 519.795 690080.000 5336140.000 518.880</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336140.000 518.880 690100.000 5336160.000 519.795 690080.000 5336160.000 519.442 690080.000 5336140.000 518.880</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336140.000 519.233 690120.000 5336140.000 519.586 690120.000 5336160.000 520.148 690100.000 5336140.000 519.233</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336140.000 519.233 690120.000 5336160.000 520.148 690100.000 5336160.000 519.795 690100.000 5336140.000 519.233</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336140.000 519.586 690140.000 5336140.000 519.939 690140.000 5336160.000 520.501 690120.000 5336140.000 519.586</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336140.000 519.586 690140.000 5336160.000 520.501 690120.000 5336160.000 520.148 690120.000 5336140.000 519.586</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336140.000 519.939 690160.000 5336140.000 520.292 690160.000 5336160.000 520.854 690140.000 5336140.000 519.939</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336140.000 519.939 690160.000 5336160.000 520.854 690140.000 5336160.000 520.501 690140.000 5336140.000 519.939</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336140.000 520.292 690180.000 5336140.000 520.645 690180.000 5336160.000 521.207 690160.000 5336140.000 520.292</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336140.000 520.292 690180.000 5336160.000 521.207 690160.000 5336160.000 520.854 690160.000 5336140.000 520.292</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336140.000 520.645 690200.000 5336140.000 520.998 690200.000 5336160.000 521.560 690180.000 5336140.000 520.645</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336140.000 520.645 690200.000 5336160.000 521.560 690180.000 5336160.000 521.207 690180.000 5336140.000 520.645</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336140.000 520.998 690220.000 5336140.000 521.351 690220.000 5336160.000 521.913 690200.000 5336140.000 520.998</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336140.000 520.998 690220.000 5336160.000 521.913 690200.000 5336160.000 521.560 690200.000 5336140.000 520.998</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336140.000 521.351 690240.000 5336140.000 521.704 690240.000 5336160.000 522.266 690220.000 5336140.000 521.351</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336140.000 521.351 690240.000 5336160.000 522.266 690220.000 5336160.000 521.913 690220.000 5336140.000 521.351</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336140.000 521.704 690260.000 5336140.000 522.057 690260.000 5336160.000 522.619 690240.000 5336140.000 521.704</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336140.000 521.704 690260.000 5336160.000 522.619 690240.000 5336160.000 522.266 690240.000 5336140.000 521.704</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336140.000 522.057 690280.000 5336140.000 522.410 690280.000 5336160.000 522.972 690260.000 5336140.000 522.057</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336140.000 522.057 690280.000 5336160.000 522.972 690260.000 5336160.000 522.619 690260.000 5336140.000 522.057</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336140.000 522.410 690300.000 5336140.000 522.763 690300.000 5336160.000 523.325 690280.000 5336140.000 522.410</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336140.000 522.410 690300.000 5336160.000 523.325 690280.000 5336160.000 522.972 690280.000 5336140.000 522.410</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336140.000 522.763 690320.000 5336140.000 523.116 690320.000 5336160.000 523.678 690300.000 5336140.000 522.763</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336140.000 522.763 690320.000 5336160.000 523.678 690300.000 5336160.000 523.325 690300.000 5336140.000 522.763</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336160.000 517.678 690000.000 5336160.000 518.031 690000.000 5336180.000 518.659 689980.000 5336160.000 517.678</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336160.000 517.678 690000.000 5336180.000 518.659 689980.000 5336180.000 518.306 689980.000 5336160.000 517.678</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336160.000 518.031 690020.000 5336160.000 518.384 690020.000 5336180.000 519.012 690000.000 5336160.000 518.031</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336160.000 518.031 690020.000 5336180.000 519.012 690000.000 5336180.000 518.659 690000.000 5336160.000 518.031</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336160.000 518.384 690040.000 5336160.000 518.737 690040.000 5336180.000 519.365 690020.000 5336160.000 518.384</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336160.000 518.384 690040.000 5336180.000 519.365 690020.000 5336180.000 519.012 690020.000 5336160.000 518.384</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336160.000 518.737 690060.000 5336160.000 519.089 690060.000 5336180.000 519.718 690040.000 5336160.000 518.737</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336160.000 518.737 690060.000 5336180.000 519.718 690040.000 5336180.000 519.365 690040.000 5336160.000 518.737</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336160.000 519.089 690080.000 5336160.000 519.442 690080.000 5336180.000 520.070 690060.000 5336160.000 519.089</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336160.000 519.089 690080.000 5336180.000 520.070 690060.000 5336180.000 519.718 690060.000 5336160.000 519.089</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336160.000 519.442 690100.000 5336160.000 519.795 690100.000 5336180.000 520.423 690080.000 5336160.000 519.442</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336160.000 519.442 690100.000 5336180.000 520.423 690080.000 5336180.000 520.070 690080.000 5336160.000 519.442</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336160.000 519.795 690120.000 5336160.000 520.148 690120.000 5336180.000 520.776 690100.000 5336160.000 519.795</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336160.000 519.795 690120.000 5336180.000 520.776 690100.000 5336180.000 520.423 690100.000 5336160.000 519.795</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336160.000 520.148 690140.000 5336160.000 520.501 690140.000 5336180.000 521.129 690120.000 5336160.000 520.148</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336160.000 520.148 690140.000 5336180.000 521.129 690120.000 5336180.000 520.776 690120.000 5336160.000 520.148</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336160.000 520.501 690160.000 5336160.000 520.854 690160.000 5336180.000 521.482 690140.000 5336160.000 520.501</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336160.000 520.501 690160.000 5336180.000 521.482 690140.000 5336180.000 521.129 690140.000 5336160.000 520.501</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336160.000 520.854 690180.000 5336160.000 521.207 690180.000 5336180.000 521.835 690160.000 5336160.000 520.854</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336160.000 520.854 690180.000 5336180.000 521.835 690160.000 5336180.000 521.482 690160.000 5336160.000 520.854</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336160.000 521.207 690200.000 5336160.000 521.560 690200.000 5336180.000 522.188 690180.000 5336160.000 521.207</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336160.000 521.207 690200.000 5336180.000 522.188 690180.000 5336180.000 521.835 690180.000 5336160.000 521.207</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336160.000 521.560 690220.000 5336160.000 521.913 690220.000 5336180.000 522.541 690200.000 5336160.000 521.560</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336160.000 521.560 690220.000 5336180.000 522.541 690200.000 5336180.000 522.188 690200.000 5336160.000 521.560</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336160.000 521.913 690240.000 5336160.000 522.266 690240.000 5336180.000 522.894 690220.000 5336160.000 521.913</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336160.000 521.913 690240.000 5336180.000 522.894 690220.000 5336180.000 522.541 690220.000 5336160.000 521.913</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336160.000 522.266 690260.000 5336160.000 522.619 690260.000 5336180.000 523.247 690240.000 5336160.000 522.266</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336160.000 522.266 690260.000 5336180.000 523.247 690240.000 5336180.000 522.894 690240.000 5336160.000 522.266</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336160.000 522.619 690280.000 5336160.000 522.972 690280.000 5336180.000 523.600 690260.000 5336160.000 522.619</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336160.000 522.619 690280.000 5336180.000 523.600 690260.000 5336180.000 523.247 690260.000 5336160.000 522.619</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336160.000 522.972 690300.000 5336160.000 523.325 690300.000 5336180.000 523.953 690280.000 5336160.000 522.972</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336160.000 522.972 690300.000 5336180.000 523.953 690280.000 5336180.000 523.600 690280.000 5336160.000 522.972</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336160.000 523.325 690320.000 5336160.000 523.678 690320.000 5336180.000 524.306 690300.000 5336160.000 523.325</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336160.000 523.325 690320.000 5336180.000 524.306 690300.000 5336180.000 523.953 690300.000 5336160.000 523.325</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336180.000 518.306 690000.000 5336180.000 518.659 690000.000 5336200.000 519.353 689980.000 5336180.000 518.306</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">689980.000 5336180.000 518.306 690000.000 5336200.000 519.353 689980.000 5336200.000 519.000 689980.000 5336180.000 518.306</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336180.000 518.659 690020.000 5336180.000 519.012 690020.000 5336200.000 519.706 690000.000 5336180.000 518.659</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690000.000 5336180.000 518.659 690020.000 5336200.000 519.706 690000.000 5336200.000 519.353 690000.000 5336180.000 518.659</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336180.000 519.012 690040.000 5336180.000 519.365 690040.000 5336200.000 520.059 690020.000 5336180.000 519.012</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690020.000 5336180.000 519.012 690040.000 5336200.000 520.059 690020.000 5336200.000 519.706 690020.000 5336180.000 519.012</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336180.000 519.365 690060.000 5336180.000 519.718 690060.000 5336200.000 520.412 690040.000 5336180.000 519.365</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690040.000 5336180.000 519.365 690060.000 5336200.000 520.412 690040.000 5336200.000 520.059 690040.000 5336180.000 519.365</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336180.000 519.718 690080.000 5336180.000 520.070 690080.000 5336200.000 520.765 690060.000 5336180.000 519.718</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690060.000 5336180.000 519.718 690080.000 5336200.000 520.765 690060.000 5336200.000 520.412 690060.000 5336180.000 519.718</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336180.000 520.070 690100.000 5336180.000 520.423 690100.000 5336200.000 521.118 690080.000 5336180.000 520.070</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.000 5336180.000 520.070 690100.000 5336200.000 521.118 690080.000 5336200.000 520.765 690080.000 5336180.000 520.070</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336180.000 520.423 690120.000 5336180.000 520.776 690120.000 5336200.000 521.471 690100.000 5336180.000 520.423</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.000 5336180.000 520.423 690120.000 5336200.000 521.471 690100.000 5336200.000 521.118 690100.000 5336180.000 520.423</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336180.000 520.776 690140.000 5336180.000 521.129 690140.000 5336200.000 521.824 690120.000 5336180.000 520.776</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690120.000 5336180.000 520.776 690140.000 5336200.000 521.824 690120.000 5336200.000 521.471 690120.000 5336180.000 520.776</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336180.000 521.129 690160.000 5336180.000 521.482 690160.000 5336200.000 522.176 690140.000 5336180.000 521.129</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690140.000 5336180.000 521.129 690160.000 5336200.000 522.176 690140.000 5336200.000 521.824 690140.000 5336180.000 521.129</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336180.000 521.482 690180.000 5336180.000 521.835 690180.000 5336200.000 522.529 690160.000 5336180.000 521.482</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690160.000 5336180.000 521.482 690180.000 5336200.000 522.529 690160.000 5336200.000 522.176 690160.000 5336180.000 521.482</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336180.000 521.835 690200.000 5336180.000 522.188 690200.000 5336200.000 522.882 690180.000 5336180.000 521.835</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690180.000 5336180.000 521.835 690200.000 5336200.000 522.882 690180.000 5336200.000 522.529 690180.000 5336180.000 521.835</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336180.000 522.188 690220.000 5336180.000 522.541 690220.000 5336200.000 523.235 690200.000 5336180.000 522.188</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.000 5336180.000 522.188 690220.000 5336200.000 523.235 690200.000 5336200.000 522.882 690200.000 5336180.000 522.188</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336180.000 522.541 690240.000 5336180.000 522.894 690240.000 5336200.000 523.588 690220.000 5336180.000 522.541</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690220.000 5336180.000 522.541 690240.000 5336200.000 523.588 690220.000 5336200.000 523.235 690220.000 5336180.000 522.541</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336180.000 522.894 690260.000 5336180.000 523.247 690260.000 5336200.000 523.941 690240.000 5336180.000 522.894</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690240.000 5336180.000 522.894 690260.000 5336200.000 523.941 690240.000 5336200.000 523.588 690240.000 5336180.000 522.894</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336180.000 523.247 690280.000 5336180.000 523.600 690280.000 5336200.000 524.294 690260.000 5336180.000 523.247</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690260.000 5336180.000 523.247 690280.000 5336200.000 524.294 690260.000 5336200.000 523.941 690260.000 5336180.000 523.247</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336180.000 523.600 690300.000 5336180.000 523.953 690300.000 5336200.000 524.647 690280.000 5336180.000 523.600</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690280.000 5336180.000 523.600 690300.000 5336200.000 524.647 690280.000 5336200.000 524.294 690280.000 5336180.000 523.600</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336180.000 523.953 690320.000 5336180.000 524.306 690320.000 5336200.000 525.000 690300.000 5336180.000 523.953</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
                <gml:Triangle>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690300.000 5336180.000 523.953 690320.000 5336200.000 525.000 690300.000 5336200.000 524.647 690300.000 5336180.000 523.953</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Triangle>
              </gml:trianglePatches>
            </gml:TriangulatedSurface>
          </dem:tin>
        </dem:TINRelief>
      </dem:reliefComponent>
    </dem:ReliefFeature>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000001">
      <gml:name>SC_B000001</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690002.000 5336002.000 515.431</gml:lowerCorner>
          <gml:upperCorner>690058.000 5336046.000 527.431</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>1</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>515.431</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1745</bldg:yearOfConstruction>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">12.000</bldg:measuredHeight>
      <bldg:storeysAboveGround>4</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000001_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000001_cs">
              <gml:surfaceMember xlink:href="#SC_B000001_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000001_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000001_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000001_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000001_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000001_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000001_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000001_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000001_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000001_p10"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000001_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000001_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690002.000 5336002.000 527.431 690058.000 5336002.000 527.431 690058.000 5336046.000 527.431 690002.000 5336046.000 527.431 690002.000 5336002.000 527.431</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690013.300 5336034.700 527.431 690046.700 5336034.700 527.431 690046.700 5336013.300 527.431 690013.300 5336013.300 527.431 690013.300 5336034.700 527.431</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000001_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000001_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690002.000 5336002.000 515.431 690058.000 5336002.000 515.431 690058.000 5336002.000 527.431 690002.000 5336002.000 527.431 690002.000 5336002.000 515.431</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000001_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000001_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690058.000 5336002.000 515.431 690058.000 5336046.000 515.431 690058.000 5336046.000 527.431 690058.000 5336002.000 527.431 690058.000 5336002.000 515.431</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000001_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000001_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690058.000 5336046.000 515.431 690002.000 5336046.000 515.431 690002.000 5336046.000 527.431 690058.000 5336046.000 527.431 690058.000 5336046.000 515.431</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000001_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000001_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690002.000 5336046.000 515.431 690002.000 5336002.000 515.431 690002.000 5336002.000 527.431 690002.000 5336046.000 527.431 690002.000 5336046.000 515.431</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000001_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000001_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690013.300 5336034.700 515.431 690046.700 5336034.700 515.431 690046.700 5336034.700 527.431 690013.300 5336034.700 527.431 690013.300 5336034.700 515.431</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000001_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000001_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690046.700 5336034.700 515.431 690046.700 5336013.300 515.431 690046.700 5336013.300 527.431 690046.700 5336034.700 527.431 690046.700 5336034.700 515.431</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000001_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000001_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690046.700 5336013.300 515.431 690013.300 5336013.300 515.431 690013.300 5336013.300 527.431 690046.700 5336013.300 527.431 690046.700 5336013.300 515.431</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000001_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000001_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690013.300 5336013.300 515.431 690013.300 5336034.700 515.431 690013.300 5336034.700 527.431 690013.300 5336013.300 527.431 690013.300 5336013.300 515.431</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000001_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000001_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690002.000 5336046.000 515.431 690058.000 5336046.000 515.431 690058.000 5336002.000 515.431 690002.000 5336002.000 515.431 690002.000 5336046.000 515.431</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690013.300 5336013.300 515.431 690046.700 5336013.300 515.431 690046.700 5336034.700 515.431 690013.300 5336034.700 515.431 690013.300 5336013.300 515.431</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000002">
      <gml:name>SC_B000002</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690079.400 5336003.000 516.802</gml:lowerCorner>
          <gml:upperCorner>690096.600 5336016.500 538.039</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>5</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>516.802</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1985</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">14.600</bldg:measuredHeight>
      <bldg:storeysAboveGround>3</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000002_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000002_cs">
              <gml:surfaceMember xlink:href="#SC_B000002_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000002_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000002_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000002_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000002_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000002_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000002_p7"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000002_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000002_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690091.600 5336003.000 525.802 690091.600 5336016.500 525.802 690085.500 5336016.500 531.402 690085.500 5336003.000 531.402 690091.600 5336003.000 525.802</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000002_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000002_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690079.400 5336016.500 525.802 690079.400 5336003.000 525.802 690085.500 5336003.000 531.402 690085.500 5336016.500 531.402 690079.400 5336016.500 525.802</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000002_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000002_p3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000002_p3_r0">
                      <gml:posList srsDimension="3">690091.600 5336003.000 516.802 690091.600 5336016.500 516.802 690091.600 5336016.500 525.802 690091.600 5336003.000 525.802 690091.600 5336003.000 516.802</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000002_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000002_p4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000002_p4_r0">
                      <gml:posList srsDimension="3">690091.600 5336016.500 516.802 690079.400 5336016.500 516.802 690079.400 5336016.500 525.802 690085.500 5336016.500 531.402 690091.600 5336016.500 525.802 690091.600 5336016.500 516.802</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000002_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000002_p5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000002_p5_r0">
                      <gml:posList srsDimension="3">690079.400 5336016.500 516.802 690079.400 5336003.000 516.802 690079.400 5336003.000 525.802 690079.400 5336016.500 525.802 690079.400 5336016.500 516.802</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000002_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000002_p6">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000002_p6_r0">
                      <gml:posList srsDimension="3">690079.400 5336003.000 516.802 690091.600 5336003.000 516.802 690091.600 5336003.000 525.802 690085.500 5336003.000 531.402 690079.400 5336003.000 525.802 690079.400 5336003.000 516.802</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000002_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000002_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690079.400 5336003.000 516.802 690079.400 5336016.500 516.802 690091.600 5336016.500 516.802 690091.600 5336003.000 516.802 690079.400 5336003.000 516.802</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:consistsOfBuildingPart>
        <bldg:BuildingPart gml:id="SC_B000002_part1">
          <gml:name>SC_B000002_part1</gml:name>
          <gml:boundedBy>
            <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
              <gml:lowerCorner>690091.600 5336007.250 517.039</gml:lowerCorner>
              <gml:upperCorner>690096.600 5336012.250 538.039</gml:upperCorner>
            </gml:Envelope>
          </gml:boundedBy>
          <gen:intAttribute name="Parzelle">
            <gen:value>5</gen:value>
          </gen:intAttribute>
          <gen:doubleAttribute name="HoeheGrund">
            <gen:value>517.039</gen:value>
          </gen:doubleAttribute>
          <bldg:function>1010</bldg:function>
          <bldg:yearOfConstruction>1991</bldg:yearOfConstruction>
          <bldg:roofType>1000</bldg:roofType>
          <bldg:measuredHeight uom="urn:adv:uom:m">21.000</bldg:measuredHeight>
          <bldg:storeysAboveGround>7</bldg:storeysAboveGround>
          <bldg:lod2Solid>
            <gml:Solid gml:id="SC_B000002_part1_solid">
              <gml:exterior>
                <gml:CompositeSurface gml:id="SC_B000002_part1_cs">
                  <gml:surfaceMember xlink:href="#SC_B000002_part1_p1"/>
                  <gml:surfaceMember xlink:href="#SC_B000002_part1_p2"/>
                  <gml:surfaceMember xlink:href="#SC_B000002_part1_p3"/>
                  <gml:surfaceMember xlink:href="#SC_B000002_part1_p4"/>
                  <gml:surfaceMember xlink:href="#SC_B000002_part1_p5"/>
                  <gml:surfaceMember xlink:href="#SC_B000002_part1_p6"/>
                </gml:CompositeSurface>
              </gml:exterior>
            </gml:Solid>
          </bldg:lod2Solid>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="SC_B000002_part1_s1">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000002_part1_p1">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690091.600 5336007.250 538.039 690096.600 5336007.250 538.039 690096.600 5336012.250 538.039 690091.600 5336012.250 538.039 690091.600 5336007.250 538.039</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000002_part1_s2">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000002_part1_p2">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690091.600 5336007.250 517.039 690096.600 5336007.250 517.039 690096.600 5336007.250 538.039 690091.600 5336007.250 538.039 690091.600 5336007.250 517.039</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000002_part1_s3">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000002_part1_p3">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690096.600 5336007.250 517.039 690096.600 5336012.250 517.039 690096.600 5336012.250 538.039 690096.600 5336007.250 538.039 690096.600 5336007.250 517.039</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000002_part1_s4">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000002_part1_p4">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690096.600 5336012.250 517.039 690091.600 5336012.250 517.039 690091.600 5336012.250 538.039 690096.600 5336012.250 538.039 690096.600 5336012.250 517.039</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000002_part1_s5">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000002_part1_p5">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690091.600 5336012.250 517.039 690091.600 5336007.250 517.039 690091.600 5336007.250 538.039 690091.600 5336012.250 538.039 690091.600 5336012.250 517.039</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:GroundSurface gml:id="SC_B000002_part1_s6">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000002_part1_p6">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690091.600 5336012.250 517.039 690096.600 5336012.250 517.039 690096.600 5336007.250 517.039 690091.600 5336007.250 517.039 690091.600 5336012.250 517.039</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:GroundSurface>
          </bldg:boundedBy>
        </bldg:BuildingPart>
      </bldg:consistsOfBuildingPart>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000003">
      <gml:name>SC_B000003</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690112.200 5336003.000 517.381</gml:lowerCorner>
          <gml:upperCorner>690125.900 5336013.900 526.381</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>6</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>517.381</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1892</bldg:yearOfConstruction>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">9.000</bldg:measuredHeight>
      <bldg:storeysAboveGround>3</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000003_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000003_cs">
              <gml:surfaceMember xlink:href="#SC_B000003_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000003_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000003_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000003_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000003_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000003_p6"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000003_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000003_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690112.200 5336003.000 526.381 690125.900 5336003.000 526.381 690125.900 5336013.900 526.381 690112.200 5336013.900 526.381 690112.200 5336003.000 526.381</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000003_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000003_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690112.200 5336003.000 517.381 690125.900 5336003.000 517.381 690125.900 5336003.000 526.381 690112.200 5336003.000 526.381 690112.200 5336003.000 517.381</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000003_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000003_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690125.900 5336003.000 517.381 690125.900 5336013.900 517.381 690125.900 5336013.900 526.381 690125.900 5336003.000 526.381 690125.900 5336003.000 517.381</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000003_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000003_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690125.900 5336013.900 517.381 690112.200 5336013.900 517.381 690112.200 5336013.900 526.381 690125.900 5336013.900 526.381 690125.900 5336013.900 517.381</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000003_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000003_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690112.200 5336013.900 517.381 690112.200 5336003.000 517.381 690112.200 5336003.000 526.381 690112.200 5336013.900 526.381 690112.200 5336013.900 517.381</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000003_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000003_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690112.200 5336013.900 517.381 690125.900 5336013.900 517.381 690125.900 5336003.000 517.381 690112.200 5336003.000 517.381 690112.200 5336013.900 517.381</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000004">
      <gml:name>SC_B000004</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690158.700 5336003.000 518.202</gml:lowerCorner>
          <gml:upperCorner>690174.500 5336017.700 539.402</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>9</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>518.202</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1963</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">21.200</bldg:measuredHeight>
      <bldg:storeysAboveGround>5</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000004_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000004_cs">
              <gml:surfaceMember xlink:href="#SC_B000004_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000004_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000004_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000004_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000004_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000004_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000004_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000004_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000004_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000004_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000004_p11"/>
              <gml:surfaceMember xlink:href="#SC_B000004_p12"/>
              <gml:surfaceMember xlink:href="#SC_B000004_p13"/>
              <gml:surfaceMember xlink:href="#SC_B000004_p14"/>
              <gml:surfaceMember xlink:href="#SC_B000004_p15"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000004_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690158.700 5336003.000 533.202 690174.500 5336003.000 533.202 690174.500 5336010.350 539.402 690158.700 5336010.350 539.402 690158.700 5336003.000 533.202</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690161.650 5336004.470 534.442 690161.650 5336008.145 537.542 690163.650 5336008.145 537.542 690163.650 5336004.470 534.442 690161.650 5336004.470 534.442</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.550 5336004.617 534.566 690169.550 5336007.998 537.418 690171.550 5336007.998 537.418 690171.550 5336004.617 534.566 690169.550 5336004.617 534.566</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000004_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690174.500 5336017.700 533.202 690158.700 5336017.700 533.202 690158.700 5336010.350 539.402 690174.500 5336010.350 539.402 690174.500 5336017.700 533.202</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000004_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690161.650 5336004.470 534.442 690163.650 5336004.470 534.442 690163.650 5336004.470 537.542 690161.650 5336004.470 537.542 690161.650 5336004.470 534.442</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690163.650 5336004.470 534.442 690163.650 5336008.145 537.542 690163.650 5336004.470 537.542 690163.650 5336004.470 534.442</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690161.650 5336004.470 534.442 690161.650 5336004.470 537.542 690161.650 5336008.145 537.542 690161.650 5336004.470 534.442</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000004_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690161.650 5336004.470 537.542 690163.650 5336004.470 537.542 690163.650 5336008.145 537.542 690161.650 5336008.145 537.542 690161.650 5336004.470 537.542</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000004_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.550 5336004.617 534.566 690171.550 5336004.617 534.566 690171.550 5336004.617 537.418 690169.550 5336004.617 537.418 690169.550 5336004.617 534.566</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690171.550 5336004.617 534.566 690171.550 5336007.998 537.418 690171.550 5336004.617 537.418 690171.550 5336004.617 534.566</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.550 5336004.617 534.566 690169.550 5336004.617 537.418 690169.550 5336007.998 537.418 690169.550 5336004.617 534.566</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000004_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.550 5336004.617 537.418 690171.550 5336004.617 537.418 690171.550 5336007.998 537.418 690169.550 5336007.998 537.418 690169.550 5336004.617 537.418</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000004_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690158.700 5336003.000 518.202 690174.500 5336003.000 518.202 690174.500 5336003.000 533.202 690158.700 5336003.000 533.202 690158.700 5336003.000 518.202</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000004_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p12">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690174.500 5336003.000 518.202 690174.500 5336017.700 518.202 690174.500 5336017.700 533.202 690174.500 5336010.350 539.402 690174.500 5336003.000 533.202 690174.500 5336003.000 518.202</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000004_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p13">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690174.500 5336017.700 518.202 690158.700 5336017.700 518.202 690158.700 5336017.700 533.202 690174.500 5336017.700 533.202 690174.500 5336017.700 518.202</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000004_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p14">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690158.700 5336017.700 518.202 690158.700 5336003.000 518.202 690158.700 5336003.000 533.202 690158.700 5336010.350 539.402 690158.700 5336017.700 533.202 690158.700 5336017.700 518.202</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000004_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000004_p15">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690158.700 5336017.700 518.202 690174.500 5336017.700 518.202 690174.500 5336003.000 518.202 690158.700 5336003.000 518.202 690158.700 5336017.700 518.202</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000005">
      <gml:name>SC_B000005</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690186.000 5336003.000 518.683</gml:lowerCorner>
          <gml:upperCorner>690203.000 5336019.100 531.383</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>10</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>518.683</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1794</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">12.700</bldg:measuredHeight>
      <bldg:storeysAboveGround>2</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000005_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000005_cs">
              <gml:surfaceMember xlink:href="#SC_B000005_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000005_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000005_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000005_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000005_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000005_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000005_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000005_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000005_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000005_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000005_p11"/>
              <gml:surfaceMember xlink:href="#SC_B000005_p12"/>
              <gml:surfaceMember xlink:href="#SC_B000005_p13"/>
              <gml:surfaceMember xlink:href="#SC_B000005_p14"/>
              <gml:surfaceMember xlink:href="#SC_B000005_p15"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000005_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690186.000 5336003.000 524.683 690203.000 5336003.000 524.683 690203.000 5336011.050 531.383 690186.000 5336011.050 531.383 690186.000 5336003.000 524.683</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690189.250 5336004.610 526.023 690189.250 5336008.635 529.373 690191.250 5336008.635 529.373 690191.250 5336004.610 526.023 690189.250 5336004.610 526.023</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690197.750 5336004.771 526.157 690197.750 5336008.474 529.239 690199.750 5336008.474 529.239 690199.750 5336004.771 526.157 690197.750 5336004.771 526.157</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000005_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690203.000 5336019.100 524.683 690186.000 5336019.100 524.683 690186.000 5336011.050 531.383 690203.000 5336011.050 531.383 690203.000 5336019.100 524.683</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000005_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690189.250 5336004.610 526.023 690191.250 5336004.610 526.023 690191.250 5336004.610 529.373 690189.250 5336004.610 529.373 690189.250 5336004.610 526.023</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690191.250 5336004.610 526.023 690191.250 5336008.635 529.373 690191.250 5336004.610 529.373 690191.250 5336004.610 526.023</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690189.250 5336004.610 526.023 690189.250 5336004.610 529.373 690189.250 5336008.635 529.373 690189.250 5336004.610 526.023</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000005_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690189.250 5336004.610 529.373 690191.250 5336004.610 529.373 690191.250 5336008.635 529.373 690189.250 5336008.635 529.373 690189.250 5336004.610 529.373</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000005_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690197.750 5336004.771 526.157 690199.750 5336004.771 526.157 690199.750 5336004.771 529.239 690197.750 5336004.771 529.239 690197.750 5336004.771 526.157</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690199.750 5336004.771 526.157 690199.750 5336008.474 529.239 690199.750 5336004.771 529.239 690199.750 5336004.771 526.157</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690197.750 5336004.771 526.157 690197.750 5336004.771 529.239 690197.750 5336008.474 529.239 690197.750 5336004.771 526.157</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000005_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690197.750 5336004.771 529.239 690199.750 5336004.771 529.239 690199.750 5336008.474 529.239 690197.750 5336008.474 529.239 690197.750 5336004.771 529.239</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000005_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690186.000 5336003.000 518.683 690203.000 5336003.000 518.683 690203.000 5336003.000 524.683 690186.000 5336003.000 524.683 690186.000 5336003.000 518.683</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000005_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p12">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690203.000 5336003.000 518.683 690203.000 5336019.100 518.683 690203.000 5336019.100 524.683 690203.000 5336011.050 531.383 690203.000 5336003.000 524.683 690203.000 5336003.000 518.683</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000005_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p13">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690203.000 5336019.100 518.683 690186.000 5336019.100 518.683 690186.000 5336019.100 524.683 690203.000 5336019.100 524.683 690203.000 5336019.100 518.683</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000005_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p14">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690186.000 5336019.100 518.683 690186.000 5336003.000 518.683 690186.000 5336003.000 524.683 690186.000 5336011.050 531.383 690186.000 5336019.100 524.683 690186.000 5336019.100 518.683</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000005_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000005_p15">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690186.000 5336019.100 518.683 690203.000 5336019.100 518.683 690203.000 5336003.000 518.683 690186.000 5336003.000 518.683 690186.000 5336019.100 518.683</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000006">
      <gml:name>SC_B000006</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690155.900 5336027.400 518.298</gml:lowerCorner>
          <gml:upperCorner>690178.000 5336045.000 531.798</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>11</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>518.298</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1947</bldg:yearOfConstruction>
      <bldg:roofType>3200</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">13.500</bldg:measuredHeight>
      <bldg:storeysAboveGround>2</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000006_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000006_cs">
              <gml:surfaceMember xlink:href="#SC_B000006_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000006_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000006_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000006_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000006_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000006_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000006_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000006_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000006_p9"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000006_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000006_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690155.900 5336027.400 524.298 690178.000 5336027.400 524.298 690169.200 5336036.200 531.798 690164.700 5336036.200 531.798 690155.900 5336027.400 524.298</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000006_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000006_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690178.000 5336045.000 524.298 690155.900 5336045.000 524.298 690164.700 5336036.200 531.798 690169.200 5336036.200 531.798 690178.000 5336045.000 524.298</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000006_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000006_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690178.000 5336027.400 524.298 690178.000 5336045.000 524.298 690169.200 5336036.200 531.798 690178.000 5336027.400 524.298</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000006_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000006_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690155.900 5336045.000 524.298 690155.900 5336027.400 524.298 690164.700 5336036.200 531.798 690155.900 5336045.000 524.298</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000006_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000006_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690155.900 5336027.400 518.298 690178.000 5336027.400 518.298 690178.000 5336027.400 524.298 690155.900 5336027.400 524.298 690155.900 5336027.400 518.298</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000006_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000006_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690178.000 5336027.400 518.298 690178.000 5336045.000 518.298 690178.000 5336045.000 524.298 690178.000 5336027.400 524.298 690178.000 5336027.400 518.298</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000006_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000006_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690178.000 5336045.000 518.298 690155.900 5336045.000 518.298 690155.900 5336045.000 524.298 690178.000 5336045.000 524.298 690178.000 5336045.000 518.298</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000006_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000006_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690155.900 5336045.000 518.298 690155.900 5336027.400 518.298 690155.900 5336027.400 524.298 690155.900 5336045.000 524.298 690155.900 5336045.000 518.298</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000006_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000006_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690155.900 5336045.000 518.298 690178.000 5336045.000 518.298 690178.000 5336027.400 518.298 690155.900 5336027.400 518.298 690155.900 5336045.000 518.298</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000007">
      <gml:name>SC_B000007</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690185.400 5336033.700 518.870</gml:lowerCorner>
          <gml:upperCorner>690205.600 5336045.000 546.165</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>12</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>518.870</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1724</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">18.200</bldg:measuredHeight>
      <bldg:storeysAboveGround>5</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000007_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000007_cs">
              <gml:surfaceMember xlink:href="#SC_B000007_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000007_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000007_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000007_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000007_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000007_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000007_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000007_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000007_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000007_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000007_p11"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000007_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000007_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690185.400 5336033.700 533.870 690200.600 5336033.700 533.870 690200.600 5336039.350 537.070 690185.400 5336039.350 537.070 690185.400 5336033.700 533.870</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690192.000 5336034.830 534.510 690192.000 5336037.655 536.110 690194.000 5336037.655 536.110 690194.000 5336034.830 534.510 690192.000 5336034.830 534.510</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000007_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000007_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.600 5336045.000 533.870 690185.400 5336045.000 533.870 690185.400 5336039.350 537.070 690200.600 5336039.350 537.070 690200.600 5336045.000 533.870</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000007_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000007_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690192.000 5336034.830 534.510 690194.000 5336034.830 534.510 690194.000 5336034.830 536.110 690192.000 5336034.830 536.110 690192.000 5336034.830 534.510</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000007_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690194.000 5336034.830 534.510 690194.000 5336037.655 536.110 690194.000 5336034.830 536.110 690194.000 5336034.830 534.510</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000007_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690192.000 5336034.830 534.510 690192.000 5336034.830 536.110 690192.000 5336037.655 536.110 690192.000 5336034.830 534.510</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000007_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000007_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690192.000 5336034.830 536.110 690194.000 5336034.830 536.110 690194.000 5336037.655 536.110 690192.000 5336037.655 536.110 690192.000 5336034.830 536.110</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000007_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000007_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690185.400 5336033.700 518.870 690200.600 5336033.700 518.870 690200.600 5336033.700 533.870 690185.400 5336033.700 533.870 690185.400 5336033.700 518.870</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000007_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000007_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.600 5336033.700 518.870 690200.600 5336045.000 518.870 690200.600 5336045.000 533.870 690200.600 5336039.350 537.070 690200.600 5336033.700 533.870 690200.600 5336033.700 518.870</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000007_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000007_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690200.600 5336045.000 518.870 690185.400 5336045.000 518.870 690185.400 5336045.000 533.870 690200.600 5336045.000 533.870 690200.600 5336045.000 518.870</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000007_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000007_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690185.400 5336045.000 518.870 690185.400 5336033.700 518.870 690185.400 5336033.700 533.870 690185.400 5336039.350 537.070 690185.400 5336045.000 533.870 690185.400 5336045.000 518.870</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000007_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000007_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690185.400 5336045.000 518.870 690200.600 5336045.000 518.870 690200.600 5336033.700 518.870 690185.400 5336033.700 518.870 690185.400 5336045.000 518.870</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:consistsOfBuildingPart>
        <bldg:BuildingPart gml:id="SC_B000007_part1">
          <gml:name>SC_B000007_part1</gml:name>
          <gml:boundedBy>
            <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
              <gml:lowerCorner>690200.600 5336036.850 519.165</gml:lowerCorner>
              <gml:upperCorner>690205.600 5336041.850 546.165</gml:upperCorner>
            </gml:Envelope>
          </gml:boundedBy>
          <gen:intAttribute name="Parzelle">
            <gen:value>12</gen:value>
          </gen:intAttribute>
          <gen:doubleAttribute name="HoeheGrund">
            <gen:value>519.165</gen:value>
          </gen:doubleAttribute>
          <bldg:function>1010</bldg:function>
          <bldg:yearOfConstruction>1876</bldg:yearOfConstruction>
          <bldg:roofType>1000</bldg:roofType>
          <bldg:measuredHeight uom="urn:adv:uom:m">27.000</bldg:measuredHeight>
          <bldg:storeysAboveGround>9</bldg:storeysAboveGround>
          <bldg:lod2Solid>
            <gml:Solid gml:id="SC_B000007_part1_solid">
              <gml:exterior>
                <gml:CompositeSurface gml:id="SC_B000007_part1_cs">
                  <gml:surfaceMember xlink:href="#SC_B000007_part1_p1"/>
                  <gml:surfaceMember xlink:href="#SC_B000007_part1_p2"/>
                  <gml:surfaceMember xlink:href="#SC_B000007_part1_p3"/>
                  <gml:surfaceMember xlink:href="#SC_B000007_part1_p4"/>
                  <gml:surfaceMember xlink:href="#SC_B000007_part1_p5"/>
                  <gml:surfaceMember xlink:href="#SC_B000007_part1_p6"/>
                </gml:CompositeSurface>
              </gml:exterior>
            </gml:Solid>
          </bldg:lod2Solid>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="SC_B000007_part1_s1">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000007_part1_p1">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690200.600 5336036.850 546.165 690205.600 5336036.850 546.165 690205.600 5336041.850 546.165 690200.600 5336041.850 546.165 690200.600 5336036.850 546.165</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000007_part1_s2">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000007_part1_p2">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690200.600 5336036.850 519.165 690205.600 5336036.850 519.165 690205.600 5336036.850 546.165 690200.600 5336036.850 546.165 690200.600 5336036.850 519.165</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000007_part1_s3">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000007_part1_p3">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690205.600 5336036.850 519.165 690205.600 5336041.850 519.165 690205.600 5336041.850 546.165 690205.600 5336036.850 546.165 690205.600 5336036.850 519.165</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000007_part1_s4">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000007_part1_p4">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690205.600 5336041.850 519.165 690200.600 5336041.850 519.165 690200.600 5336041.850 546.165 690205.600 5336041.850 546.165 690205.600 5336041.850 519.165</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000007_part1_s5">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000007_part1_p5">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690200.600 5336041.850 519.165 690200.600 5336036.850 519.165 690200.600 5336036.850 546.165 690200.600 5336041.850 546.165 690200.600 5336041.850 519.165</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:GroundSurface gml:id="SC_B000007_part1_s6">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000007_part1_p6">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690200.600 5336041.850 519.165 690205.600 5336041.850 519.165 690205.600 5336036.850 519.165 690200.600 5336036.850 519.165 690200.600 5336041.850 519.165</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:GroundSurface>
          </bldg:boundedBy>
        </bldg:BuildingPart>
      </bldg:consistsOfBuildingPart>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000008">
      <gml:name>SC_B000008</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690238.400 5336003.000 519.608</gml:lowerCorner>
          <gml:upperCorner>690254.700 5336020.100 530.608</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>13</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>519.608</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1779</bldg:yearOfConstruction>
      <bldg:yearOfDemolition>1872</bldg:yearOfDemolition>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">11.000</bldg:measuredHeight>
      <bldg:storeysAboveGround>2</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000008_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000008_cs">
              <gml:surfaceMember xlink:href="#SC_B000008_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000008_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000008_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000008_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000008_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000008_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000008_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000008_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000008_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000008_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000008_p11"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000008_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000008_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690254.700 5336003.000 525.608 690254.700 5336020.100 525.608 690246.550 5336020.100 530.608 690246.550 5336003.000 530.608 690254.700 5336003.000 525.608</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690253.070 5336010.550 526.608 690248.995 5336010.550 529.108 690248.995 5336012.550 529.108 690253.070 5336012.550 526.608 690253.070 5336010.550 526.608</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000008_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000008_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690238.400 5336020.100 525.608 690238.400 5336003.000 525.608 690246.550 5336003.000 530.608 690246.550 5336020.100 530.608 690238.400 5336020.100 525.608</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000008_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000008_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690253.070 5336010.550 526.608 690253.070 5336012.550 526.608 690253.070 5336012.550 529.108 690253.070 5336010.550 529.108 690253.070 5336010.550 526.608</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000008_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690253.070 5336012.550 526.608 690248.995 5336012.550 529.108 690253.070 5336012.550 529.108 690253.070 5336012.550 526.608</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000008_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690253.070 5336010.550 526.608 690253.070 5336010.550 529.108 690248.995 5336010.550 529.108 690253.070 5336010.550 526.608</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000008_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000008_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690253.070 5336010.550 529.108 690253.070 5336012.550 529.108 690248.995 5336012.550 529.108 690248.995 5336010.550 529.108 690253.070 5336010.550 529.108</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000008_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000008_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690254.700 5336003.000 519.608 690254.700 5336020.100 519.608 690254.700 5336020.100 525.608 690254.700 5336003.000 525.608 690254.700 5336003.000 519.608</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000008_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000008_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690254.700 5336020.100 519.608 690238.400 5336020.100 519.608 690238.400 5336020.100 525.608 690246.550 5336020.100 530.608 690254.700 5336020.100 525.608 690254.700 5336020.100 519.608</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000008_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000008_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690238.400 5336020.100 519.608 690238.400 5336003.000 519.608 690238.400 5336003.000 525.608 690238.400 5336020.100 525.608 690238.400 5336020.100 519.608</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000008_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000008_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690238.400 5336003.000 519.608 690254.700 5336003.000 519.608 690254.700 5336003.000 525.608 690246.550 5336003.000 530.608 690238.400 5336003.000 525.608 690238.400 5336003.000 519.608</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000008_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000008_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690238.400 5336003.000 519.608 690238.400 5336020.100 519.608 690254.700 5336020.100 519.608 690254.700 5336003.000 519.608 690238.400 5336003.000 519.608</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000009">
      <gml:name>SC_B000009</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690263.300 5336003.000 520.047</gml:lowerCorner>
          <gml:upperCorner>690283.600 5336017.100 532.747</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>14</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>520.047</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1940</bldg:yearOfConstruction>
      <bldg:roofType>3200</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">12.700</bldg:measuredHeight>
      <bldg:storeysAboveGround>2</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000009_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000009_cs">
              <gml:surfaceMember xlink:href="#SC_B000009_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000009_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000009_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000009_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000009_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000009_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000009_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000009_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000009_p9"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000009_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000009_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690263.300 5336003.000 526.047 690283.600 5336003.000 526.047 690276.550 5336010.050 532.747 690270.350 5336010.050 532.747 690263.300 5336003.000 526.047</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000009_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000009_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690283.600 5336017.100 526.047 690263.300 5336017.100 526.047 690270.350 5336010.050 532.747 690276.550 5336010.050 532.747 690283.600 5336017.100 526.047</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000009_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000009_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690283.600 5336003.000 526.047 690283.600 5336017.100 526.047 690276.550 5336010.050 532.747 690283.600 5336003.000 526.047</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000009_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000009_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690263.300 5336017.100 526.047 690263.300 5336003.000 526.047 690270.350 5336010.050 532.747 690263.300 5336017.100 526.047</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000009_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000009_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690263.300 5336003.000 520.047 690283.600 5336003.000 520.047 690283.600 5336003.000 526.047 690263.300 5336003.000 526.047 690263.300 5336003.000 520.047</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000009_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000009_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690283.600 5336003.000 520.047 690283.600 5336017.100 520.047 690283.600 5336017.100 526.047 690283.600 5336003.000 526.047 690283.600 5336003.000 520.047</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000009_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000009_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690283.600 5336017.100 520.047 690263.300 5336017.100 520.047 690263.300 5336017.100 526.047 690283.600 5336017.100 526.047 690283.600 5336017.100 520.047</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000009_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000009_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690263.300 5336017.100 520.047 690263.300 5336003.000 520.047 690263.300 5336003.000 526.047 690263.300 5336017.100 526.047 690263.300 5336017.100 520.047</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000009_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000009_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690263.300 5336017.100 520.047 690283.600 5336017.100 520.047 690283.600 5336003.000 520.047 690263.300 5336003.000 520.047 690263.300 5336017.100 520.047</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000010">
      <gml:name>SC_B000010</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690262.800 5336033.400 520.234</gml:lowerCorner>
          <gml:upperCorner>690275.600 5336045.000 529.134</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>16</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>520.234</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1707</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">8.900</bldg:measuredHeight>
      <bldg:storeysAboveGround>2</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000010_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000010_cs">
              <gml:surfaceMember xlink:href="#SC_B000010_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000010_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000010_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000010_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000010_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000010_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000010_p7"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000010_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000010_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690262.800 5336033.400 526.234 690275.600 5336033.400 526.234 690275.600 5336039.200 529.134 690262.800 5336039.200 529.134 690262.800 5336033.400 526.234</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000010_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000010_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690275.600 5336045.000 526.234 690262.800 5336045.000 526.234 690262.800 5336039.200 529.134 690275.600 5336039.200 529.134 690275.600 5336045.000 526.234</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000010_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000010_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690262.800 5336033.400 520.234 690275.600 5336033.400 520.234 690275.600 5336033.400 526.234 690262.800 5336033.400 526.234 690262.800 5336033.400 520.234</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000010_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000010_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690275.600 5336033.400 520.234 690275.600 5336045.000 520.234 690275.600 5336045.000 526.234 690275.600 5336039.200 529.134 690275.600 5336033.400 526.234 690275.600 5336033.400 520.234</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000010_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000010_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690275.600 5336045.000 520.234 690262.800 5336045.000 520.234 690262.800 5336045.000 526.234 690275.600 5336045.000 526.234 690275.600 5336045.000 520.234</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000010_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000010_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690262.800 5336045.000 520.234 690262.800 5336033.400 520.234 690262.800 5336033.400 526.234 690262.800 5336039.200 529.134 690262.800 5336045.000 526.234 690262.800 5336045.000 520.234</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000010_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000010_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690262.800 5336045.000 520.234 690275.600 5336045.000 520.234 690275.600 5336033.400 520.234 690262.800 5336033.400 520.234 690262.800 5336045.000 520.234</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000011">
      <gml:name>SC_B000011</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690009.500 5336067.000 516.154</gml:lowerCorner>
          <gml:upperCorner>690025.900 5336077.900 531.154</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>17</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>516.154</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1730</bldg:yearOfConstruction>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">15.000</bldg:measuredHeight>
      <bldg:storeysAboveGround>5</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000011_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000011_cs">
              <gml:surfaceMember xlink:href="#SC_B000011_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000011_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000011_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000011_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000011_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000011_p6"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000011_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000011_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690009.500 5336067.000 531.154 690025.900 5336067.000 531.154 690025.900 5336077.900 531.154 690009.500 5336077.900 531.154 690009.500 5336067.000 531.154</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000011_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000011_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690009.500 5336067.000 516.154 690025.900 5336067.000 516.154 690025.900 5336067.000 531.154 690009.500 5336067.000 531.154 690009.500 5336067.000 516.154</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000011_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000011_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690025.900 5336067.000 516.154 690025.900 5336077.900 516.154 690025.900 5336077.900 531.154 690025.900 5336067.000 531.154 690025.900 5336067.000 516.154</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000011_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000011_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690025.900 5336077.900 516.154 690009.500 5336077.900 516.154 690009.500 5336077.900 531.154 690025.900 5336077.900 531.154 690025.900 5336077.900 516.154</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000011_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000011_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690009.500 5336077.900 516.154 690009.500 5336067.000 516.154 690009.500 5336067.000 531.154 690009.500 5336077.900 531.154 690009.500 5336077.900 516.154</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000011_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000011_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690009.500 5336077.900 516.154 690025.900 5336077.900 516.154 690025.900 5336067.000 516.154 690009.500 5336067.000 516.154 690009.500 5336077.900 516.154</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000012">
      <gml:name>SC_B000012</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690039.200 5336067.000 516.678</gml:lowerCorner>
          <gml:upperCorner>690051.400 5336084.700 531.778</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>18</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>516.678</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1909</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">15.100</bldg:measuredHeight>
      <bldg:storeysAboveGround>4</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000012_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000012_cs">
              <gml:surfaceMember xlink:href="#SC_B000012_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p11"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p12"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p13"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p14"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p15"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p16"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p17"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p18"/>
              <gml:surfaceMember xlink:href="#SC_B000012_p19"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000012_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690051.400 5336067.000 528.678 690051.400 5336084.700 528.678 690045.300 5336084.700 531.778 690045.300 5336067.000 531.778 690051.400 5336067.000 528.678</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690050.180 5336068.950 529.298 690047.130 5336068.950 530.848 690047.130 5336070.950 530.848 690050.180 5336070.950 529.298 690050.180 5336068.950 529.298</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690050.058 5336074.850 529.360 690047.252 5336074.850 530.786 690047.252 5336076.850 530.786 690050.058 5336076.850 529.360 690050.058 5336074.850 529.360</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690049.936 5336080.750 529.422 690047.374 5336080.750 530.724 690047.374 5336082.750 530.724 690049.936 5336082.750 529.422 690049.936 5336080.750 529.422</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000012_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690039.200 5336084.700 528.678 690039.200 5336067.000 528.678 690045.300 5336067.000 531.778 690045.300 5336084.700 531.778 690039.200 5336084.700 528.678</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000012_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690050.180 5336068.950 529.298 690050.180 5336070.950 529.298 690050.180 5336070.950 530.848 690050.180 5336068.950 530.848 690050.180 5336068.950 529.298</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690050.180 5336070.950 529.298 690047.130 5336070.950 530.848 690050.180 5336070.950 530.848 690050.180 5336070.950 529.298</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690050.180 5336068.950 529.298 690050.180 5336068.950 530.848 690047.130 5336068.950 530.848 690050.180 5336068.950 529.298</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000012_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690050.180 5336068.950 530.848 690050.180 5336070.950 530.848 690047.130 5336070.950 530.848 690047.130 5336068.950 530.848 690050.180 5336068.950 530.848</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000012_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690050.058 5336074.850 529.360 690050.058 5336076.850 529.360 690050.058 5336076.850 530.786 690050.058 5336074.850 530.786 690050.058 5336074.850 529.360</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690050.058 5336076.850 529.360 690047.252 5336076.850 530.786 690050.058 5336076.850 530.786 690050.058 5336076.850 529.360</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690050.058 5336074.850 529.360 690050.058 5336074.850 530.786 690047.252 5336074.850 530.786 690050.058 5336074.850 529.360</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000012_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690050.058 5336074.850 530.786 690050.058 5336076.850 530.786 690047.252 5336076.850 530.786 690047.252 5336074.850 530.786 690050.058 5336074.850 530.786</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000012_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690049.936 5336080.750 529.422 690049.936 5336082.750 529.422 690049.936 5336082.750 530.724 690049.936 5336080.750 530.724 690049.936 5336080.750 529.422</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p12">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690049.936 5336082.750 529.422 690047.374 5336082.750 530.724 690049.936 5336082.750 530.724 690049.936 5336082.750 529.422</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p13">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690049.936 5336080.750 529.422 690049.936 5336080.750 530.724 690047.374 5336080.750 530.724 690049.936 5336080.750 529.422</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000012_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p14">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690049.936 5336080.750 530.724 690049.936 5336082.750 530.724 690047.374 5336082.750 530.724 690047.374 5336080.750 530.724 690049.936 5336080.750 530.724</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000012_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p15">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690051.400 5336067.000 516.678 690051.400 5336084.700 516.678 690051.400 5336084.700 528.678 690051.400 5336067.000 528.678 690051.400 5336067.000 516.678</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000012_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p16">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690051.400 5336084.700 516.678 690039.200 5336084.700 516.678 690039.200 5336084.700 528.678 690045.300 5336084.700 531.778 690051.400 5336084.700 528.678 690051.400 5336084.700 516.678</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000012_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p17">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690039.200 5336084.700 516.678 690039.200 5336067.000 516.678 690039.200 5336067.000 528.678 690039.200 5336084.700 528.678 690039.200 5336084.700 516.678</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000012_s12">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p18">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690039.200 5336067.000 516.678 690051.400 5336067.000 516.678 690051.400 5336067.000 528.678 690045.300 5336067.000 531.778 690039.200 5336067.000 528.678 690039.200 5336067.000 516.678</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000012_s13">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000012_p19">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690039.200 5336067.000 516.678 690039.200 5336084.700 516.678 690051.400 5336084.700 516.678 690051.400 5336067.000 516.678 690039.200 5336067.000 516.678</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000013">
      <gml:name>SC_B000013</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690004.800 5336092.700 516.495</gml:lowerCorner>
          <gml:upperCorner>690023.200 5336109.000 539.595</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>19</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>516.495</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1922</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">23.100</bldg:measuredHeight>
      <bldg:storeysAboveGround>5</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000013_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000013_cs">
              <gml:surfaceMember xlink:href="#SC_B000013_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p11"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p12"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p13"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p14"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p15"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p16"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p17"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p18"/>
              <gml:surfaceMember xlink:href="#SC_B000013_p19"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000013_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690004.800 5336092.700 531.495 690023.200 5336092.700 531.495 690023.200 5336100.850 539.595 690004.800 5336100.850 539.595 690004.800 5336092.700 531.495</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690006.867 5336094.330 533.115 690006.867 5336098.405 537.165 690008.867 5336098.405 537.165 690008.867 5336094.330 533.115 690006.867 5336094.330 533.115</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690013.000 5336094.493 533.277 690013.000 5336098.242 537.003 690015.000 5336098.242 537.003 690015.000 5336094.493 533.277 690013.000 5336094.493 533.277</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690019.133 5336094.656 533.439 690019.133 5336098.079 536.841 690021.133 5336098.079 536.841 690021.133 5336094.656 533.439 690019.133 5336094.656 533.439</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000013_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690023.200 5336109.000 531.495 690004.800 5336109.000 531.495 690004.800 5336100.850 539.595 690023.200 5336100.850 539.595 690023.200 5336109.000 531.495</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000013_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690006.867 5336094.330 533.115 690008.867 5336094.330 533.115 690008.867 5336094.330 537.165 690006.867 5336094.330 537.165 690006.867 5336094.330 533.115</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690008.867 5336094.330 533.115 690008.867 5336098.405 537.165 690008.867 5336094.330 537.165 690008.867 5336094.330 533.115</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690006.867 5336094.330 533.115 690006.867 5336094.330 537.165 690006.867 5336098.405 537.165 690006.867 5336094.330 533.115</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000013_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690006.867 5336094.330 537.165 690008.867 5336094.330 537.165 690008.867 5336098.405 537.165 690006.867 5336098.405 537.165 690006.867 5336094.330 537.165</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000013_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690013.000 5336094.493 533.277 690015.000 5336094.493 533.277 690015.000 5336094.493 537.003 690013.000 5336094.493 537.003 690013.000 5336094.493 533.277</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690015.000 5336094.493 533.277 690015.000 5336098.242 537.003 690015.000 5336094.493 537.003 690015.000 5336094.493 533.277</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690013.000 5336094.493 533.277 690013.000 5336094.493 537.003 690013.000 5336098.242 537.003 690013.000 5336094.493 533.277</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000013_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690013.000 5336094.493 537.003 690015.000 5336094.493 537.003 690015.000 5336098.242 537.003 690013.000 5336098.242 537.003 690013.000 5336094.493 537.003</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000013_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690019.133 5336094.656 533.439 690021.133 5336094.656 533.439 690021.133 5336094.656 536.841 690019.133 5336094.656 536.841 690019.133 5336094.656 533.439</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p12">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690021.133 5336094.656 533.439 690021.133 5336098.079 536.841 690021.133 5336094.656 536.841 690021.133 5336094.656 533.439</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p13">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690019.133 5336094.656 533.439 690019.133 5336094.656 536.841 690019.133 5336098.079 536.841 690019.133 5336094.656 533.439</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000013_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p14">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690019.133 5336094.656 536.841 690021.133 5336094.656 536.841 690021.133 5336098.079 536.841 690019.133 5336098.079 536.841 690019.133 5336094.656 536.841</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000013_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p15">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690004.800 5336092.700 516.495 690023.200 5336092.700 516.495 690023.200 5336092.700 531.495 690004.800 5336092.700 531.495 690004.800 5336092.700 516.495</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000013_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p16">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690023.200 5336092.700 516.495 690023.200 5336109.000 516.495 690023.200 5336109.000 531.495 690023.200 5336100.850 539.595 690023.200 5336092.700 531.495 690023.200 5336092.700 516.495</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000013_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p17">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690023.200 5336109.000 516.495 690004.800 5336109.000 516.495 690004.800 5336109.000 531.495 690023.200 5336109.000 531.495 690023.200 5336109.000 516.495</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000013_s12">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p18">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690004.800 5336109.000 516.495 690004.800 5336092.700 516.495 690004.800 5336092.700 531.495 690004.800 5336100.850 539.595 690004.800 5336109.000 531.495 690004.800 5336109.000 516.495</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000013_s13">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000013_p19">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690004.800 5336109.000 516.495 690023.200 5336109.000 516.495 690023.200 5336092.700 516.495 690004.800 5336092.700 516.495 690004.800 5336109.000 516.495</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000014">
      <gml:name>SC_B000014</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690034.800 5336096.800 517.099</gml:lowerCorner>
          <gml:upperCorner>690051.900 5336109.000 538.379</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>20</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>517.099</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1809</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">19.400</bldg:measuredHeight>
      <bldg:storeysAboveGround>5</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000014_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000014_cs">
              <gml:surfaceMember xlink:href="#SC_B000014_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p11"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p12"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p13"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p14"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p15"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p16"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p17"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p18"/>
              <gml:surfaceMember xlink:href="#SC_B000014_p19"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000014_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690046.900 5336096.800 532.099 690046.900 5336109.000 532.099 690040.850 5336109.000 536.499 690040.850 5336096.800 536.499 690046.900 5336096.800 532.099</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.690 5336097.833 532.979 690042.665 5336097.833 535.179 690042.665 5336099.833 535.179 690045.690 5336099.833 532.979 690045.690 5336097.833 532.979</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.569 5336101.900 533.067 690042.786 5336101.900 535.091 690042.786 5336103.900 535.091 690045.569 5336103.900 533.067 690045.569 5336101.900 533.067</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.448 5336105.967 533.155 690042.907 5336105.967 535.003 690042.907 5336107.967 535.003 690045.448 5336107.967 533.155 690045.448 5336105.967 533.155</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000014_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690034.800 5336109.000 532.099 690034.800 5336096.800 532.099 690040.850 5336096.800 536.499 690040.850 5336109.000 536.499 690034.800 5336109.000 532.099</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000014_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.690 5336097.833 532.979 690045.690 5336099.833 532.979 690045.690 5336099.833 535.179 690045.690 5336097.833 535.179 690045.690 5336097.833 532.979</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.690 5336099.833 532.979 690042.665 5336099.833 535.179 690045.690 5336099.833 535.179 690045.690 5336099.833 532.979</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.690 5336097.833 532.979 690045.690 5336097.833 535.179 690042.665 5336097.833 535.179 690045.690 5336097.833 532.979</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000014_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.690 5336097.833 535.179 690045.690 5336099.833 535.179 690042.665 5336099.833 535.179 690042.665 5336097.833 535.179 690045.690 5336097.833 535.179</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000014_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.569 5336101.900 533.067 690045.569 5336103.900 533.067 690045.569 5336103.900 535.091 690045.569 5336101.900 535.091 690045.569 5336101.900 533.067</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.569 5336103.900 533.067 690042.786 5336103.900 535.091 690045.569 5336103.900 535.091 690045.569 5336103.900 533.067</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.569 5336101.900 533.067 690045.569 5336101.900 535.091 690042.786 5336101.900 535.091 690045.569 5336101.900 533.067</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000014_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.569 5336101.900 535.091 690045.569 5336103.900 535.091 690042.786 5336103.900 535.091 690042.786 5336101.900 535.091 690045.569 5336101.900 535.091</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000014_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.448 5336105.967 533.155 690045.448 5336107.967 533.155 690045.448 5336107.967 535.003 690045.448 5336105.967 535.003 690045.448 5336105.967 533.155</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p12">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.448 5336107.967 533.155 690042.907 5336107.967 535.003 690045.448 5336107.967 535.003 690045.448 5336107.967 533.155</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p13">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.448 5336105.967 533.155 690045.448 5336105.967 535.003 690042.907 5336105.967 535.003 690045.448 5336105.967 533.155</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000014_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p14">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690045.448 5336105.967 535.003 690045.448 5336107.967 535.003 690042.907 5336107.967 535.003 690042.907 5336105.967 535.003 690045.448 5336105.967 535.003</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000014_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p15">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000014_p15_r0">
                      <gml:posList srsDimension="3">690046.900 5336096.800 517.099 690046.900 5336109.000 517.099 690046.900 5336109.000 532.099 690046.900 5336096.800 532.099 690046.900 5336096.800 517.099</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000014_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p16">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000014_p16_r0">
                      <gml:posList srsDimension="3">690046.900 5336109.000 517.099 690034.800 5336109.000 517.099 690034.800 5336109.000 532.099 690040.850 5336109.000 536.499 690046.900 5336109.000 532.099 690046.900 5336109.000 517.099</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000014_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p17">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000014_p17_r0">
                      <gml:posList srsDimension="3">690034.800 5336109.000 517.099 690034.800 5336096.800 517.099 690034.800 5336096.800 532.099 690034.800 5336109.000 532.099 690034.800 5336109.000 517.099</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000014_s12">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p18">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000014_p18_r0">
                      <gml:posList srsDimension="3">690034.800 5336096.800 517.099 690046.900 5336096.800 517.099 690046.900 5336096.800 532.099 690040.850 5336096.800 536.499 690034.800 5336096.800 532.099 690034.800 5336096.800 517.099</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000014_s13">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000014_p19">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690034.800 5336096.800 517.099 690034.800 5336109.000 517.099 690046.900 5336109.000 517.099 690046.900 5336096.800 517.099 690034.800 5336096.800 517.099</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:consistsOfBuildingPart>
        <bldg:BuildingPart gml:id="SC_B000014_part1">
          <gml:name>SC_B000014_part1</gml:name>
          <gml:boundedBy>
            <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
              <gml:lowerCorner>690046.900 5336100.400 517.379</gml:lowerCorner>
              <gml:upperCorner>690051.900 5336105.400 538.379</gml:upperCorner>
            </gml:Envelope>
          </gml:boundedBy>
          <gen:intAttribute name="Parzelle">
            <gen:value>20</gen:value>
          </gen:intAttribute>
          <gen:doubleAttribute name="HoeheGrund">
            <gen:value>517.379</gen:value>
          </gen:doubleAttribute>
          <bldg:function>1010</bldg:function>
          <bldg:yearOfConstruction>1852</bldg:yearOfConstruction>
          <bldg:roofType>1000</bldg:roofType>
          <bldg:measuredHeight uom="urn:adv:uom:m">21.000</bldg:measuredHeight>
          <bldg:storeysAboveGround>7</bldg:storeysAboveGround>
          <bldg:lod2Solid>
            <gml:Solid gml:id="SC_B000014_part1_solid">
              <gml:exterior>
                <gml:CompositeSurface gml:id="SC_B000014_part1_cs">
                  <gml:surfaceMember xlink:href="#SC_B000014_part1_p1"/>
                  <gml:surfaceMember xlink:href="#SC_B000014_part1_p2"/>
                  <gml:surfaceMember xlink:href="#SC_B000014_part1_p3"/>
                  <gml:surfaceMember xlink:href="#SC_B000014_part1_p4"/>
                  <gml:surfaceMember xlink:href="#SC_B000014_part1_p5"/>
                  <gml:surfaceMember xlink:href="#SC_B000014_part1_p6"/>
                </gml:CompositeSurface>
              </gml:exterior>
            </gml:Solid>
          </bldg:lod2Solid>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="SC_B000014_part1_s1">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000014_part1_p1">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690046.900 5336100.400 538.379 690051.900 5336100.400 538.379 690051.900 5336105.400 538.379 690046.900 5336105.400 538.379 690046.900 5336100.400 538.379</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000014_part1_s2">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000014_part1_p2">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690046.900 5336100.400 517.379 690051.900 5336100.400 517.379 690051.900 5336100.400 538.379 690046.900 5336100.400 538.379 690046.900 5336100.400 517.379</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000014_part1_s3">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000014_part1_p3">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690051.900 5336100.400 517.379 690051.900 5336105.400 517.379 690051.900 5336105.400 538.379 690051.900 5336100.400 538.379 690051.900 5336100.400 517.379</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000014_part1_s4">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000014_part1_p4">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690051.900 5336105.400 517.379 690046.900 5336105.400 517.379 690046.900 5336105.400 538.379 690051.900 5336105.400 538.379 690051.900 5336105.400 517.379</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000014_part1_s5">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000014_part1_p5">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690046.900 5336105.400 517.379 690046.900 5336100.400 517.379 690046.900 5336100.400 538.379 690046.900 5336105.400 538.379 690046.900 5336105.400 517.379</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:GroundSurface gml:id="SC_B000014_part1_s6">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000014_part1_p6">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690046.900 5336105.400 517.379 690051.900 5336105.400 517.379 690051.900 5336100.400 517.379 690046.900 5336100.400 517.379 690046.900 5336105.400 517.379</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:GroundSurface>
          </bldg:boundedBy>
        </bldg:BuildingPart>
      </bldg:consistsOfBuildingPart>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000015">
      <gml:name>SC_B000015</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690084.000 5336067.000 517.469</gml:lowerCorner>
          <gml:upperCorner>690101.800 5336082.200 536.769</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>21</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>517.469</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1753</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">19.300</bldg:measuredHeight>
      <bldg:storeysAboveGround>4</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000015_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000015_cs">
              <gml:surfaceMember xlink:href="#SC_B000015_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p11"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p12"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p13"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p14"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p15"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p16"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p17"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p18"/>
              <gml:surfaceMember xlink:href="#SC_B000015_p19"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000015_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690084.000 5336067.000 529.469 690101.800 5336067.000 529.469 690101.800 5336074.600 536.769 690084.000 5336074.600 536.769 690084.000 5336067.000 529.469</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690085.967 5336068.520 530.929 690085.967 5336072.320 534.579 690087.967 5336072.320 534.579 690087.967 5336068.520 530.929 690085.967 5336068.520 530.929</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690091.900 5336068.672 531.075 690091.900 5336072.168 534.433 690093.900 5336072.168 534.433 690093.900 5336068.672 531.075 690091.900 5336068.672 531.075</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690097.833 5336068.824 531.221 690097.833 5336072.016 534.287 690099.833 5336072.016 534.287 690099.833 5336068.824 531.221 690097.833 5336068.824 531.221</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000015_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690101.800 5336082.200 529.469 690084.000 5336082.200 529.469 690084.000 5336074.600 536.769 690101.800 5336074.600 536.769 690101.800 5336082.200 529.469</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000015_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690085.967 5336068.520 530.929 690087.967 5336068.520 530.929 690087.967 5336068.520 534.579 690085.967 5336068.520 534.579 690085.967 5336068.520 530.929</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690087.967 5336068.520 530.929 690087.967 5336072.320 534.579 690087.967 5336068.520 534.579 690087.967 5336068.520 530.929</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690085.967 5336068.520 530.929 690085.967 5336068.520 534.579 690085.967 5336072.320 534.579 690085.967 5336068.520 530.929</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000015_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690085.967 5336068.520 534.579 690087.967 5336068.520 534.579 690087.967 5336072.320 534.579 690085.967 5336072.320 534.579 690085.967 5336068.520 534.579</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000015_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690091.900 5336068.672 531.075 690093.900 5336068.672 531.075 690093.900 5336068.672 534.433 690091.900 5336068.672 534.433 690091.900 5336068.672 531.075</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690093.900 5336068.672 531.075 690093.900 5336072.168 534.433 690093.900 5336068.672 534.433 690093.900 5336068.672 531.075</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690091.900 5336068.672 531.075 690091.900 5336068.672 534.433 690091.900 5336072.168 534.433 690091.900 5336068.672 531.075</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000015_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690091.900 5336068.672 534.433 690093.900 5336068.672 534.433 690093.900 5336072.168 534.433 690091.900 5336072.168 534.433 690091.900 5336068.672 534.433</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000015_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690097.833 5336068.824 531.221 690099.833 5336068.824 531.221 690099.833 5336068.824 534.287 690097.833 5336068.824 534.287 690097.833 5336068.824 531.221</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p12">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690099.833 5336068.824 531.221 690099.833 5336072.016 534.287 690099.833 5336068.824 534.287 690099.833 5336068.824 531.221</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p13">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690097.833 5336068.824 531.221 690097.833 5336068.824 534.287 690097.833 5336072.016 534.287 690097.833 5336068.824 531.221</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000015_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p14">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690097.833 5336068.824 534.287 690099.833 5336068.824 534.287 690099.833 5336072.016 534.287 690097.833 5336072.016 534.287 690097.833 5336068.824 534.287</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000015_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p15">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690084.000 5336067.000 517.469 690101.800 5336067.000 517.469 690101.800 5336067.000 529.469 690084.000 5336067.000 529.469 690084.000 5336067.000 517.469</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000015_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p16">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690101.800 5336067.000 517.469 690101.800 5336082.200 517.469 690101.800 5336082.200 529.469 690101.800 5336074.600 536.769 690101.800 5336067.000 529.469 690101.800 5336067.000 517.469</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000015_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p17">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690101.800 5336082.200 517.469 690084.000 5336082.200 517.469 690084.000 5336082.200 529.469 690101.800 5336082.200 529.469 690101.800 5336082.200 517.469</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000015_s12">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p18">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690084.000 5336082.200 517.469 690084.000 5336067.000 517.469 690084.000 5336067.000 529.469 690084.000 5336074.600 536.769 690084.000 5336082.200 529.469 690084.000 5336082.200 517.469</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000015_s13">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000015_p19">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690084.000 5336082.200 517.469 690101.800 5336082.200 517.469 690101.800 5336067.000 517.469 690084.000 5336067.000 517.469 690084.000 5336082.200 517.469</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000016">
      <gml:name>SC_B000016</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690116.000 5336067.000 518.033</gml:lowerCorner>
          <gml:upperCorner>690132.700 5336080.200 527.033</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>22</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>518.033</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1745</bldg:yearOfConstruction>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">9.000</bldg:measuredHeight>
      <bldg:storeysAboveGround>3</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000016_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000016_cs">
              <gml:surfaceMember xlink:href="#SC_B000016_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000016_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000016_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000016_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000016_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000016_p6"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000016_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000016_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690116.000 5336067.000 527.033 690132.700 5336067.000 527.033 690132.700 5336080.200 527.033 690116.000 5336080.200 527.033 690116.000 5336067.000 527.033</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000016_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000016_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690116.000 5336067.000 518.033 690132.700 5336067.000 518.033 690132.700 5336067.000 527.033 690116.000 5336067.000 527.033 690116.000 5336067.000 518.033</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000016_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000016_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690132.700 5336067.000 518.033 690132.700 5336080.200 518.033 690132.700 5336080.200 527.033 690132.700 5336067.000 527.033 690132.700 5336067.000 518.033</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000016_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000016_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690132.700 5336080.200 518.033 690116.000 5336080.200 518.033 690116.000 5336080.200 527.033 690132.700 5336080.200 527.033 690132.700 5336080.200 518.033</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000016_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000016_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690116.000 5336080.200 518.033 690116.000 5336067.000 518.033 690116.000 5336067.000 527.033 690116.000 5336080.200 527.033 690116.000 5336080.200 518.033</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000016_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000016_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690116.000 5336080.200 518.033 690132.700 5336080.200 518.033 690132.700 5336067.000 518.033 690116.000 5336067.000 518.033 690116.000 5336080.200 518.033</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000017">
      <gml:name>SC_B000017</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690111.300 5336096.200 518.438</gml:lowerCorner>
          <gml:upperCorner>690131.200 5336109.000 530.738</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>24</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>518.438</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1830</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">12.300</bldg:measuredHeight>
      <bldg:storeysAboveGround>2</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000017_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000017_cs">
              <gml:surfaceMember xlink:href="#SC_B000017_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000017_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000017_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000017_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000017_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000017_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000017_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000017_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000017_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000017_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000017_p11"/>
              <gml:surfaceMember xlink:href="#SC_B000017_p12"/>
              <gml:surfaceMember xlink:href="#SC_B000017_p13"/>
              <gml:surfaceMember xlink:href="#SC_B000017_p14"/>
              <gml:surfaceMember xlink:href="#SC_B000017_p15"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000017_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690111.300 5336096.200 524.438 690131.200 5336096.200 524.438 690131.200 5336102.600 530.738 690111.300 5336102.600 530.738 690111.300 5336096.200 524.438</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690115.275 5336097.480 525.698 690115.275 5336100.680 528.848 690117.275 5336100.680 528.848 690117.275 5336097.480 525.698 690115.275 5336097.480 525.698</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690125.225 5336097.608 525.824 690125.225 5336100.552 528.722 690127.225 5336100.552 528.722 690127.225 5336097.608 525.824 690125.225 5336097.608 525.824</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000017_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690131.200 5336109.000 524.438 690111.300 5336109.000 524.438 690111.300 5336102.600 530.738 690131.200 5336102.600 530.738 690131.200 5336109.000 524.438</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000017_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690115.275 5336097.480 525.698 690117.275 5336097.480 525.698 690117.275 5336097.480 528.848 690115.275 5336097.480 528.848 690115.275 5336097.480 525.698</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690117.275 5336097.480 525.698 690117.275 5336100.680 528.848 690117.275 5336097.480 528.848 690117.275 5336097.480 525.698</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690115.275 5336097.480 525.698 690115.275 5336097.480 528.848 690115.275 5336100.680 528.848 690115.275 5336097.480 525.698</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000017_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690115.275 5336097.480 528.848 690117.275 5336097.480 528.848 690117.275 5336100.680 528.848 690115.275 5336100.680 528.848 690115.275 5336097.480 528.848</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000017_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690125.225 5336097.608 525.824 690127.225 5336097.608 525.824 690127.225 5336097.608 528.722 690125.225 5336097.608 528.722 690125.225 5336097.608 525.824</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690127.225 5336097.608 525.824 690127.225 5336100.552 528.722 690127.225 5336097.608 528.722 690127.225 5336097.608 525.824</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690125.225 5336097.608 525.824 690125.225 5336097.608 528.722 690125.225 5336100.552 528.722 690125.225 5336097.608 525.824</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000017_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690125.225 5336097.608 528.722 690127.225 5336097.608 528.722 690127.225 5336100.552 528.722 690125.225 5336100.552 528.722 690125.225 5336097.608 528.722</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000017_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690111.300 5336096.200 518.438 690131.200 5336096.200 518.438 690131.200 5336096.200 524.438 690111.300 5336096.200 524.438 690111.300 5336096.200 518.438</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000017_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p12">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690131.200 5336096.200 518.438 690131.200 5336109.000 518.438 690131.200 5336109.000 524.438 690131.200 5336102.600 530.738 690131.200 5336096.200 524.438 690131.200 5336096.200 518.438</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000017_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p13">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690131.200 5336109.000 518.438 690111.300 5336109.000 518.438 690111.300 5336109.000 524.438 690131.200 5336109.000 524.438 690131.200 5336109.000 518.438</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000017_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p14">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690111.300 5336109.000 518.438 690111.300 5336096.200 518.438 690111.300 5336096.200 524.438 690111.300 5336102.600 530.738 690111.300 5336109.000 524.438 690111.300 5336109.000 518.438</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000017_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000017_p15">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690111.300 5336109.000 518.438 690131.200 5336109.000 518.438 690131.200 5336096.200 518.438 690111.300 5336096.200 518.438 690111.300 5336109.000 518.438</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000018">
      <gml:name>SC_B000018</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690157.300 5336067.000 518.762</gml:lowerCorner>
          <gml:upperCorner>690172.200 5336081.700 531.762</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>25</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>518.762</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1972</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">13.000</bldg:measuredHeight>
      <bldg:storeysAboveGround>2</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000018_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000018_cs">
              <gml:surfaceMember xlink:href="#SC_B000018_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000018_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000018_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000018_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000018_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000018_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000018_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000018_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000018_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000018_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000018_p11"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000018_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000018_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690157.300 5336067.000 524.762 690172.200 5336067.000 524.762 690172.200 5336074.350 531.762 690157.300 5336074.350 531.762 690157.300 5336067.000 524.762</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690163.750 5336068.470 526.162 690163.750 5336072.145 529.662 690165.750 5336072.145 529.662 690165.750 5336068.470 526.162 690163.750 5336068.470 526.162</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000018_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000018_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690172.200 5336081.700 524.762 690157.300 5336081.700 524.762 690157.300 5336074.350 531.762 690172.200 5336074.350 531.762 690172.200 5336081.700 524.762</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000018_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000018_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690163.750 5336068.470 526.162 690165.750 5336068.470 526.162 690165.750 5336068.470 529.662 690163.750 5336068.470 529.662 690163.750 5336068.470 526.162</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000018_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690165.750 5336068.470 526.162 690165.750 5336072.145 529.662 690165.750 5336068.470 529.662 690165.750 5336068.470 526.162</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000018_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690163.750 5336068.470 526.162 690163.750 5336068.470 529.662 690163.750 5336072.145 529.662 690163.750 5336068.470 526.162</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000018_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000018_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690163.750 5336068.470 529.662 690165.750 5336068.470 529.662 690165.750 5336072.145 529.662 690163.750 5336072.145 529.662 690163.750 5336068.470 529.662</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000018_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000018_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690157.300 5336067.000 518.762 690172.200 5336067.000 518.762 690172.200 5336067.000 524.762 690157.300 5336067.000 524.762 690157.300 5336067.000 518.762</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000018_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000018_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690172.200 5336067.000 518.762 690172.200 5336081.700 518.762 690172.200 5336081.700 524.762 690172.200 5336074.350 531.762 690172.200 5336067.000 524.762 690172.200 5336067.000 518.762</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000018_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000018_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690172.200 5336081.700 518.762 690157.300 5336081.700 518.762 690157.300 5336081.700 524.762 690172.200 5336081.700 524.762 690172.200 5336081.700 518.762</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000018_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000018_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690157.300 5336081.700 518.762 690157.300 5336067.000 518.762 690157.300 5336067.000 524.762 690157.300 5336074.350 531.762 690157.300 5336081.700 524.762 690157.300 5336081.700 518.762</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000018_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000018_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690157.300 5336081.700 518.762 690172.200 5336081.700 518.762 690172.200 5336067.000 518.762 690157.300 5336067.000 518.762 690157.300 5336081.700 518.762</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000019">
      <gml:name>SC_B000019</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690187.500 5336067.000 519.295</gml:lowerCorner>
          <gml:upperCorner>690205.800 5336077.100 529.795</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>26</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>519.295</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1867</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">10.500</bldg:measuredHeight>
      <bldg:storeysAboveGround>2</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000019_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000019_cs">
              <gml:surfaceMember xlink:href="#SC_B000019_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000019_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000019_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000019_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000019_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000019_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000019_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000019_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000019_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000019_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000019_p11"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000019_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000019_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690187.500 5336067.000 525.295 690205.800 5336067.000 525.295 690205.800 5336072.050 529.795 690187.500 5336072.050 529.795 690187.500 5336067.000 525.295</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690195.650 5336068.010 526.195 690195.650 5336070.535 528.445 690197.650 5336070.535 528.445 690197.650 5336068.010 526.195 690195.650 5336068.010 526.195</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000019_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000019_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690205.800 5336077.100 525.295 690187.500 5336077.100 525.295 690187.500 5336072.050 529.795 690205.800 5336072.050 529.795 690205.800 5336077.100 525.295</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000019_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000019_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690195.650 5336068.010 526.195 690197.650 5336068.010 526.195 690197.650 5336068.010 528.445 690195.650 5336068.010 528.445 690195.650 5336068.010 526.195</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000019_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690197.650 5336068.010 526.195 690197.650 5336070.535 528.445 690197.650 5336068.010 528.445 690197.650 5336068.010 526.195</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000019_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690195.650 5336068.010 526.195 690195.650 5336068.010 528.445 690195.650 5336070.535 528.445 690195.650 5336068.010 526.195</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000019_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000019_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690195.650 5336068.010 528.445 690197.650 5336068.010 528.445 690197.650 5336070.535 528.445 690195.650 5336070.535 528.445 690195.650 5336068.010 528.445</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000019_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000019_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690187.500 5336067.000 519.295 690205.800 5336067.000 519.295 690205.800 5336067.000 525.295 690187.500 5336067.000 525.295 690187.500 5336067.000 519.295</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000019_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000019_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690205.800 5336067.000 519.295 690205.800 5336077.100 519.295 690205.800 5336077.100 525.295 690205.800 5336072.050 529.795 690205.800 5336067.000 525.295 690205.800 5336067.000 519.295</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000019_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000019_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690205.800 5336077.100 519.295 690187.500 5336077.100 519.295 690187.500 5336077.100 525.295 690205.800 5336077.100 525.295 690205.800 5336077.100 519.295</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000019_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000019_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690187.500 5336077.100 519.295 690187.500 5336067.000 519.295 690187.500 5336067.000 525.295 690187.500 5336072.050 529.795 690187.500 5336077.100 525.295 690187.500 5336077.100 519.295</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000019_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000019_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690187.500 5336077.100 519.295 690205.800 5336077.100 519.295 690205.800 5336067.000 519.295 690187.500 5336067.000 519.295 690187.500 5336077.100 519.295</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000020">
      <gml:name>SC_B000020</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690157.700 5336094.500 519.226</gml:lowerCorner>
          <gml:upperCorner>690170.900 5336109.000 539.226</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>27</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>519.226</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1833</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">20.000</bldg:measuredHeight>
      <bldg:storeysAboveGround>5</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000020_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000020_cs">
              <gml:surfaceMember xlink:href="#SC_B000020_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p11"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p12"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p13"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p14"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p15"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p16"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p17"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p18"/>
              <gml:surfaceMember xlink:href="#SC_B000020_p19"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000020_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690170.900 5336094.500 534.226 690170.900 5336109.000 534.226 690164.300 5336109.000 539.226 690164.300 5336094.500 539.226 690170.900 5336094.500 534.226</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.580 5336095.917 535.226 690166.280 5336095.917 537.726 690166.280 5336097.917 537.726 690169.580 5336097.917 535.226 690169.580 5336095.917 535.226</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.448 5336100.750 535.326 690166.412 5336100.750 537.626 690166.412 5336102.750 537.626 690169.448 5336102.750 535.326 690169.448 5336100.750 535.326</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.316 5336105.583 535.426 690166.544 5336105.583 537.526 690166.544 5336107.583 537.526 690169.316 5336107.583 535.426 690169.316 5336105.583 535.426</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000020_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690157.700 5336109.000 534.226 690157.700 5336094.500 534.226 690164.300 5336094.500 539.226 690164.300 5336109.000 539.226 690157.700 5336109.000 534.226</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000020_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.580 5336095.917 535.226 690169.580 5336097.917 535.226 690169.580 5336097.917 537.726 690169.580 5336095.917 537.726 690169.580 5336095.917 535.226</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.580 5336097.917 535.226 690166.280 5336097.917 537.726 690169.580 5336097.917 537.726 690169.580 5336097.917 535.226</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.580 5336095.917 535.226 690169.580 5336095.917 537.726 690166.280 5336095.917 537.726 690169.580 5336095.917 535.226</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000020_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.580 5336095.917 537.726 690169.580 5336097.917 537.726 690166.280 5336097.917 537.726 690166.280 5336095.917 537.726 690169.580 5336095.917 537.726</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000020_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.448 5336100.750 535.326 690169.448 5336102.750 535.326 690169.448 5336102.750 537.626 690169.448 5336100.750 537.626 690169.448 5336100.750 535.326</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.448 5336102.750 535.326 690166.412 5336102.750 537.626 690169.448 5336102.750 537.626 690169.448 5336102.750 535.326</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.448 5336100.750 535.326 690169.448 5336100.750 537.626 690166.412 5336100.750 537.626 690169.448 5336100.750 535.326</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000020_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.448 5336100.750 537.626 690169.448 5336102.750 537.626 690166.412 5336102.750 537.626 690166.412 5336100.750 537.626 690169.448 5336100.750 537.626</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000020_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.316 5336105.583 535.426 690169.316 5336107.583 535.426 690169.316 5336107.583 537.526 690169.316 5336105.583 537.526 690169.316 5336105.583 535.426</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p12">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.316 5336107.583 535.426 690166.544 5336107.583 537.526 690169.316 5336107.583 537.526 690169.316 5336107.583 535.426</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p13">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.316 5336105.583 535.426 690169.316 5336105.583 537.526 690166.544 5336105.583 537.526 690169.316 5336105.583 535.426</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000020_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p14">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690169.316 5336105.583 537.526 690169.316 5336107.583 537.526 690166.544 5336107.583 537.526 690166.544 5336105.583 537.526 690169.316 5336105.583 537.526</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000020_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p15">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690170.900 5336094.500 519.226 690170.900 5336109.000 519.226 690170.900 5336109.000 534.226 690170.900 5336094.500 534.226 690170.900 5336094.500 519.226</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000020_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p16">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690170.900 5336109.000 519.226 690157.700 5336109.000 519.226 690157.700 5336109.000 534.226 690164.300 5336109.000 539.226 690170.900 5336109.000 534.226 690170.900 5336109.000 519.226</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000020_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p17">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690157.700 5336109.000 519.226 690157.700 5336094.500 519.226 690157.700 5336094.500 534.226 690157.700 5336109.000 534.226 690157.700 5336109.000 519.226</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000020_s12">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p18">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690157.700 5336094.500 519.226 690170.900 5336094.500 519.226 690170.900 5336094.500 534.226 690164.300 5336094.500 539.226 690157.700 5336094.500 534.226 690157.700 5336094.500 519.226</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000020_s13">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000020_p19">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690157.700 5336094.500 519.226 690157.700 5336109.000 519.226 690170.900 5336109.000 519.226 690170.900 5336094.500 519.226 690157.700 5336094.500 519.226</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000021">
      <gml:name>SC_B000021</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690188.200 5336094.700 519.768</gml:lowerCorner>
          <gml:upperCorner>690205.600 5336109.000 537.768</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>28</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>519.768</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1778</bldg:yearOfConstruction>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">18.000</bldg:measuredHeight>
      <bldg:storeysAboveGround>6</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000021_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000021_cs">
              <gml:surfaceMember xlink:href="#SC_B000021_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000021_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000021_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000021_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000021_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000021_p6"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000021_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000021_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690188.200 5336094.700 537.768 690205.600 5336094.700 537.768 690205.600 5336109.000 537.768 690188.200 5336109.000 537.768 690188.200 5336094.700 537.768</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000021_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000021_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690188.200 5336094.700 519.768 690205.600 5336094.700 519.768 690205.600 5336094.700 537.768 690188.200 5336094.700 537.768 690188.200 5336094.700 519.768</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000021_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000021_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690205.600 5336094.700 519.768 690205.600 5336109.000 519.768 690205.600 5336109.000 537.768 690205.600 5336094.700 537.768 690205.600 5336094.700 519.768</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000021_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000021_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690205.600 5336109.000 519.768 690188.200 5336109.000 519.768 690188.200 5336109.000 537.768 690205.600 5336109.000 537.768 690205.600 5336109.000 519.768</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000021_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000021_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690188.200 5336109.000 519.768 690188.200 5336094.700 519.768 690188.200 5336094.700 537.768 690188.200 5336109.000 537.768 690188.200 5336109.000 519.768</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000021_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000021_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690188.200 5336109.000 519.768 690205.600 5336109.000 519.768 690205.600 5336094.700 519.768 690188.200 5336094.700 519.768 690188.200 5336109.000 519.768</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000022">
      <gml:name>SC_B000022</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690237.100 5336098.500 520.700</gml:lowerCorner>
          <gml:upperCorner>690252.000 5336109.000 541.700</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>31</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>520.700</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1743</bldg:yearOfConstruction>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">21.000</bldg:measuredHeight>
      <bldg:storeysAboveGround>7</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000022_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000022_cs">
              <gml:surfaceMember xlink:href="#SC_B000022_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000022_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000022_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000022_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000022_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000022_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000022_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000022_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000022_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000022_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000022_p11"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000022_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000022_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690237.100 5336098.500 535.700 690252.000 5336098.500 535.700 690252.000 5336109.000 535.700 690237.100 5336109.000 535.700 690237.100 5336098.500 535.700</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690239.100 5336107.000 535.700 690250.000 5336107.000 535.700 690250.000 5336100.500 535.700 690239.100 5336100.500 535.700 690239.100 5336107.000 535.700</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000022_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000022_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690239.100 5336100.500 541.700 690250.000 5336100.500 541.700 690250.000 5336107.000 541.700 690239.100 5336107.000 541.700 690239.100 5336100.500 541.700</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000022_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000022_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690237.100 5336098.500 520.700 690252.000 5336098.500 520.700 690252.000 5336098.500 535.700 690237.100 5336098.500 535.700 690237.100 5336098.500 520.700</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000022_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000022_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690252.000 5336098.500 520.700 690252.000 5336109.000 520.700 690252.000 5336109.000 535.700 690252.000 5336098.500 535.700 690252.000 5336098.500 520.700</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000022_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000022_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690252.000 5336109.000 520.700 690237.100 5336109.000 520.700 690237.100 5336109.000 535.700 690252.000 5336109.000 535.700 690252.000 5336109.000 520.700</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000022_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000022_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690237.100 5336109.000 520.700 690237.100 5336098.500 520.700 690237.100 5336098.500 535.700 690237.100 5336109.000 535.700 690237.100 5336109.000 520.700</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000022_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000022_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690239.100 5336100.500 535.700 690250.000 5336100.500 535.700 690250.000 5336100.500 541.700 690239.100 5336100.500 541.700 690239.100 5336100.500 535.700</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000022_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000022_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690250.000 5336100.500 535.700 690250.000 5336107.000 535.700 690250.000 5336107.000 541.700 690250.000 5336100.500 541.700 690250.000 5336100.500 535.700</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000022_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000022_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690250.000 5336107.000 535.700 690239.100 5336107.000 535.700 690239.100 5336107.000 541.700 690250.000 5336107.000 541.700 690250.000 5336107.000 535.700</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000022_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000022_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690239.100 5336107.000 535.700 690239.100 5336100.500 535.700 690239.100 5336100.500 541.700 690239.100 5336107.000 541.700 690239.100 5336107.000 535.700</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000022_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000022_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690237.100 5336109.000 520.700 690252.000 5336109.000 520.700 690252.000 5336098.500 520.700 690237.100 5336098.500 520.700 690237.100 5336109.000 520.700</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000023">
      <gml:name>SC_B000023</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690268.200 5336095.100 521.187</gml:lowerCorner>
          <gml:upperCorner>690285.000 5336109.000 530.187</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>32</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>521.187</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1855</bldg:yearOfConstruction>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">9.000</bldg:measuredHeight>
      <bldg:storeysAboveGround>3</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000023_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000023_cs">
              <gml:surfaceMember xlink:href="#SC_B000023_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000023_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000023_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000023_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000023_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000023_p6"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000023_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000023_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690268.200 5336095.100 530.187 690285.000 5336095.100 530.187 690285.000 5336109.000 530.187 690268.200 5336109.000 530.187 690268.200 5336095.100 530.187</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000023_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000023_p2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000023_p2_r0">
                      <gml:posList srsDimension="3">690268.200 5336095.100 521.187 690285.000 5336095.100 521.187 690285.000 5336095.100 530.187 690268.200 5336095.100 530.187 690268.200 5336095.100 521.187</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000023_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000023_p3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000023_p3_r0">
                      <gml:posList srsDimension="3">690285.000 5336095.100 521.187 690285.000 5336109.000 521.187 690285.000 5336109.000 530.187 690285.000 5336095.100 530.187 690285.000 5336095.100 521.187</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000023_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000023_p4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000023_p4_r0">
                      <gml:posList srsDimension="3">690285.000 5336109.000 521.187 690268.200 5336109.000 521.187 690268.200 5336109.000 530.187 690285.000 5336109.000 530.187 690285.000 5336109.000 521.187</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000023_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000023_p5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000023_p5_r0">
                      <gml:posList srsDimension="3">690268.200 5336109.000 521.187 690268.200 5336095.100 521.187 690268.200 5336095.100 530.187 690268.200 5336109.000 530.187 690268.200 5336109.000 521.187</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000023_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000023_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690268.200 5336109.000 521.187 690285.000 5336109.000 521.187 690285.000 5336095.100 521.187 690268.200 5336095.100 521.187 690268.200 5336109.000 521.187</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000024">
      <gml:name>SC_B000024</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690003.000 5336131.000 517.299</gml:lowerCorner>
          <gml:upperCorner>690023.900 5336144.500 535.685</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>33</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>517.299</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1992</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">17.100</bldg:measuredHeight>
      <bldg:storeysAboveGround>4</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000024_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000024_cs">
              <gml:surfaceMember xlink:href="#SC_B000024_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p11"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p12"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p13"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p14"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p15"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p16"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p17"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p18"/>
              <gml:surfaceMember xlink:href="#SC_B000024_p19"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000024_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690003.000 5336131.000 529.299 690018.900 5336131.000 529.299 690018.900 5336137.750 534.399 690003.000 5336137.750 534.399 690003.000 5336131.000 529.299</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690004.650 5336132.350 530.319 690004.650 5336135.725 532.869 690006.650 5336135.725 532.869 690006.650 5336132.350 530.319 690004.650 5336132.350 530.319</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690009.950 5336132.485 530.421 690009.950 5336135.590 532.767 690011.950 5336135.590 532.767 690011.950 5336132.485 530.421 690009.950 5336132.485 530.421</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690015.250 5336132.620 530.523 690015.250 5336135.455 532.665 690017.250 5336135.455 532.665 690017.250 5336132.620 530.523 690015.250 5336132.620 530.523</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000024_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690018.900 5336144.500 529.299 690003.000 5336144.500 529.299 690003.000 5336137.750 534.399 690018.900 5336137.750 534.399 690018.900 5336144.500 529.299</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000024_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690004.650 5336132.350 530.319 690006.650 5336132.350 530.319 690006.650 5336132.350 532.869 690004.650 5336132.350 532.869 690004.650 5336132.350 530.319</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690006.650 5336132.350 530.319 690006.650 5336135.725 532.869 690006.650 5336132.350 532.869 690006.650 5336132.350 530.319</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690004.650 5336132.350 530.319 690004.650 5336132.350 532.869 690004.650 5336135.725 532.869 690004.650 5336132.350 530.319</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000024_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690004.650 5336132.350 532.869 690006.650 5336132.350 532.869 690006.650 5336135.725 532.869 690004.650 5336135.725 532.869 690004.650 5336132.350 532.869</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000024_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690009.950 5336132.485 530.421 690011.950 5336132.485 530.421 690011.950 5336132.485 532.767 690009.950 5336132.485 532.767 690009.950 5336132.485 530.421</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690011.950 5336132.485 530.421 690011.950 5336135.590 532.767 690011.950 5336132.485 532.767 690011.950 5336132.485 530.421</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690009.950 5336132.485 530.421 690009.950 5336132.485 532.767 690009.950 5336135.590 532.767 690009.950 5336132.485 530.421</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000024_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690009.950 5336132.485 532.767 690011.950 5336132.485 532.767 690011.950 5336135.590 532.767 690009.950 5336135.590 532.767 690009.950 5336132.485 532.767</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000024_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690015.250 5336132.620 530.523 690017.250 5336132.620 530.523 690017.250 5336132.620 532.665 690015.250 5336132.620 532.665 690015.250 5336132.620 530.523</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p12">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690017.250 5336132.620 530.523 690017.250 5336135.455 532.665 690017.250 5336132.620 532.665 690017.250 5336132.620 530.523</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p13">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690015.250 5336132.620 530.523 690015.250 5336132.620 532.665 690015.250 5336135.455 532.665 690015.250 5336132.620 530.523</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000024_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p14">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690015.250 5336132.620 532.665 690017.250 5336132.620 532.665 690017.250 5336135.455 532.665 690015.250 5336135.455 532.665 690015.250 5336132.620 532.665</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000024_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p15">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690003.000 5336131.000 517.299 690018.900 5336131.000 517.299 690018.900 5336131.000 529.299 690003.000 5336131.000 529.299 690003.000 5336131.000 517.299</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000024_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p16">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690018.900 5336131.000 517.299 690018.900 5336144.500 517.299 690018.900 5336144.500 529.299 690018.900 5336137.750 534.399 690018.900 5336131.000 529.299 690018.900 5336131.000 517.299</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000024_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p17">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690018.900 5336144.500 517.299 690003.000 5336144.500 517.299 690003.000 5336144.500 529.299 690018.900 5336144.500 529.299 690018.900 5336144.500 517.299</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000024_s12">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p18">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690003.000 5336144.500 517.299 690003.000 5336131.000 517.299 690003.000 5336131.000 529.299 690003.000 5336137.750 534.399 690003.000 5336144.500 529.299 690003.000 5336144.500 517.299</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000024_s13">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000024_p19">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690003.000 5336144.500 517.299 690018.900 5336144.500 517.299 690018.900 5336131.000 517.299 690003.000 5336131.000 517.299 690003.000 5336144.500 517.299</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:consistsOfBuildingPart>
        <bldg:BuildingPart gml:id="SC_B000024_part1">
          <gml:name>SC_B000024_part1</gml:name>
          <gml:boundedBy>
            <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
              <gml:lowerCorner>690018.900 5336135.250 517.685</gml:lowerCorner>
              <gml:upperCorner>690023.900 5336140.250 535.685</gml:upperCorner>
            </gml:Envelope>
          </gml:boundedBy>
          <gen:intAttribute name="Parzelle">
            <gen:value>33</gen:value>
          </gen:intAttribute>
          <gen:doubleAttribute name="HoeheGrund">
            <gen:value>517.685</gen:value>
          </gen:doubleAttribute>
          <bldg:function>1010</bldg:function>
          <bldg:yearOfConstruction>1994</bldg:yearOfConstruction>
          <bldg:roofType>1000</bldg:roofType>
          <bldg:measuredHeight uom="urn:adv:uom:m">18.000</bldg:measuredHeight>
          <bldg:storeysAboveGround>6</bldg:storeysAboveGround>
          <bldg:lod2Solid>
            <gml:Solid gml:id="SC_B000024_part1_solid">
              <gml:exterior>
                <gml:CompositeSurface gml:id="SC_B000024_part1_cs">
                  <gml:surfaceMember xlink:href="#SC_B000024_part1_p1"/>
                  <gml:surfaceMember xlink:href="#SC_B000024_part1_p2"/>
                  <gml:surfaceMember xlink:href="#SC_B000024_part1_p3"/>
                  <gml:surfaceMember xlink:href="#SC_B000024_part1_p4"/>
                  <gml:surfaceMember xlink:href="#SC_B000024_part1_p5"/>
                  <gml:surfaceMember xlink:href="#SC_B000024_part1_p6"/>
                </gml:CompositeSurface>
              </gml:exterior>
            </gml:Solid>
          </bldg:lod2Solid>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="SC_B000024_part1_s1">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000024_part1_p1">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690018.900 5336135.250 535.685 690023.900 5336135.250 535.685 690023.900 5336140.250 535.685 690018.900 5336140.250 535.685 690018.900 5336135.250 535.685</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000024_part1_s2">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000024_part1_p2">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690018.900 5336135.250 517.685 690023.900 5336135.250 517.685 690023.900 5336135.250 535.685 690018.900 5336135.250 535.685 690018.900 5336135.250 517.685</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000024_part1_s3">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000024_part1_p3">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690023.900 5336135.250 517.685 690023.900 5336140.250 517.685 690023.900 5336140.250 535.685 690023.900 5336135.250 535.685 690023.900 5336135.250 517.685</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000024_part1_s4">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000024_part1_p4">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690023.900 5336140.250 517.685 690018.900 5336140.250 517.685 690018.900 5336140.250 535.685 690023.900 5336140.250 535.685 690023.900 5336140.250 517.685</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="SC_B000024_part1_s5">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000024_part1_p5">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690018.900 5336140.250 517.685 690018.900 5336135.250 517.685 690018.900 5336135.250 535.685 690018.900 5336140.250 535.685 690018.900 5336140.250 517.685</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:GroundSurface gml:id="SC_B000024_part1_s6">
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="SC_B000024_part1_p6">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">690018.900 5336140.250 517.685 690023.900 5336140.250 517.685 690023.900 5336135.250 517.685 690018.900 5336135.250 517.685 690018.900 5336140.250 517.685</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:GroundSurface>
          </bldg:boundedBy>
        </bldg:BuildingPart>
      </bldg:consistsOfBuildingPart>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000025">
      <gml:name>SC_B000025</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690038.700 5336131.000 517.929</gml:lowerCorner>
          <gml:upperCorner>690055.800 5336148.300 532.129</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>34</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>517.929</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1717</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">14.200</bldg:measuredHeight>
      <bldg:storeysAboveGround>2</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000025_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000025_cs">
              <gml:surfaceMember xlink:href="#SC_B000025_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000025_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000025_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000025_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000025_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000025_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000025_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000025_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000025_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000025_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000025_p11"/>
              <gml:surfaceMember xlink:href="#SC_B000025_p12"/>
              <gml:surfaceMember xlink:href="#SC_B000025_p13"/>
              <gml:surfaceMember xlink:href="#SC_B000025_p14"/>
              <gml:surfaceMember xlink:href="#SC_B000025_p15"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000025_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690055.800 5336131.000 523.929 690055.800 5336148.300 523.929 690047.250 5336148.300 532.129 690047.250 5336131.000 532.129 690055.800 5336131.000 523.929</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690054.090 5336134.325 525.569 690049.815 5336134.325 529.669 690049.815 5336136.325 529.669 690054.090 5336136.325 525.569 690054.090 5336134.325 525.569</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690053.919 5336142.975 525.733 690049.986 5336142.975 529.505 690049.986 5336144.975 529.505 690053.919 5336144.975 525.733 690053.919 5336142.975 525.733</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000025_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690038.700 5336148.300 523.929 690038.700 5336131.000 523.929 690047.250 5336131.000 532.129 690047.250 5336148.300 532.129 690038.700 5336148.300 523.929</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000025_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690054.090 5336134.325 525.569 690054.090 5336136.325 525.569 690054.090 5336136.325 529.669 690054.090 5336134.325 529.669 690054.090 5336134.325 525.569</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690054.090 5336136.325 525.569 690049.815 5336136.325 529.669 690054.090 5336136.325 529.669 690054.090 5336136.325 525.569</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690054.090 5336134.325 525.569 690054.090 5336134.325 529.669 690049.815 5336134.325 529.669 690054.090 5336134.325 525.569</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000025_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690054.090 5336134.325 529.669 690054.090 5336136.325 529.669 690049.815 5336136.325 529.669 690049.815 5336134.325 529.669 690054.090 5336134.325 529.669</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000025_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690053.919 5336142.975 525.733 690053.919 5336144.975 525.733 690053.919 5336144.975 529.505 690053.919 5336142.975 529.505 690053.919 5336142.975 525.733</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690053.919 5336144.975 525.733 690049.986 5336144.975 529.505 690053.919 5336144.975 529.505 690053.919 5336144.975 525.733</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690053.919 5336142.975 525.733 690053.919 5336142.975 529.505 690049.986 5336142.975 529.505 690053.919 5336142.975 525.733</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000025_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690053.919 5336142.975 529.505 690053.919 5336144.975 529.505 690049.986 5336144.975 529.505 690049.986 5336142.975 529.505 690053.919 5336142.975 529.505</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000025_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690055.800 5336131.000 517.929 690055.800 5336148.300 517.929 690055.800 5336148.300 523.929 690055.800 5336131.000 523.929 690055.800 5336131.000 517.929</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000025_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p12">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690055.800 5336148.300 517.929 690038.700 5336148.300 517.929 690038.700 5336148.300 523.929 690047.250 5336148.300 532.129 690055.800 5336148.300 523.929 690055.800 5336148.300 517.929</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000025_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p13">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690038.700 5336148.300 517.929 690038.700 5336131.000 517.929 690038.700 5336131.000 523.929 690038.700 5336148.300 523.929 690038.700 5336148.300 517.929</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000025_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p14">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690038.700 5336131.000 517.929 690055.800 5336131.000 517.929 690055.800 5336131.000 523.929 690047.250 5336131.000 532.129 690038.700 5336131.000 523.929 690038.700 5336131.000 517.929</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000025_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000025_p15">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690038.700 5336131.000 517.929 690038.700 5336148.300 517.929 690055.800 5336148.300 517.929 690055.800 5336131.000 517.929 690038.700 5336131.000 517.929</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000026">
      <gml:name>SC_B000026</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690035.100 5336162.400 518.726</gml:lowerCorner>
          <gml:upperCorner>690056.700 5336173.000 537.626</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>36</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>518.726</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1780</bldg:yearOfConstruction>
      <bldg:yearOfDemolition>1896</bldg:yearOfDemolition>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">18.900</bldg:measuredHeight>
      <bldg:storeysAboveGround>5</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000026_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000026_cs">
              <gml:surfaceMember xlink:href="#SC_B000026_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000026_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000026_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000026_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000026_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000026_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000026_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000026_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000026_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000026_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000026_p11"/>
              <gml:surfaceMember xlink:href="#SC_B000026_p12"/>
              <gml:surfaceMember xlink:href="#SC_B000026_p13"/>
              <gml:surfaceMember xlink:href="#SC_B000026_p14"/>
              <gml:surfaceMember xlink:href="#SC_B000026_p15"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000026_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690035.100 5336162.400 533.726 690056.700 5336162.400 533.726 690056.700 5336167.700 537.626 690035.100 5336167.700 537.626 690035.100 5336162.400 533.726</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690039.500 5336163.460 534.506 690039.500 5336166.110 536.456 690041.500 5336166.110 536.456 690041.500 5336163.460 534.506 690039.500 5336163.460 534.506</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690050.300 5336163.566 534.584 690050.300 5336166.004 536.378 690052.300 5336166.004 536.378 690052.300 5336163.566 534.584 690050.300 5336163.566 534.584</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000026_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690056.700 5336173.000 533.726 690035.100 5336173.000 533.726 690035.100 5336167.700 537.626 690056.700 5336167.700 537.626 690056.700 5336173.000 533.726</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000026_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690039.500 5336163.460 534.506 690041.500 5336163.460 534.506 690041.500 5336163.460 536.456 690039.500 5336163.460 536.456 690039.500 5336163.460 534.506</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690041.500 5336163.460 534.506 690041.500 5336166.110 536.456 690041.500 5336163.460 536.456 690041.500 5336163.460 534.506</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690039.500 5336163.460 534.506 690039.500 5336163.460 536.456 690039.500 5336166.110 536.456 690039.500 5336163.460 534.506</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000026_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690039.500 5336163.460 536.456 690041.500 5336163.460 536.456 690041.500 5336166.110 536.456 690039.500 5336166.110 536.456 690039.500 5336163.460 536.456</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000026_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690050.300 5336163.566 534.584 690052.300 5336163.566 534.584 690052.300 5336163.566 536.378 690050.300 5336163.566 536.378 690050.300 5336163.566 534.584</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690052.300 5336163.566 534.584 690052.300 5336166.004 536.378 690052.300 5336163.566 536.378 690052.300 5336163.566 534.584</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690050.300 5336163.566 534.584 690050.300 5336163.566 536.378 690050.300 5336166.004 536.378 690050.300 5336163.566 534.584</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000026_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690050.300 5336163.566 536.378 690052.300 5336163.566 536.378 690052.300 5336166.004 536.378 690050.300 5336166.004 536.378 690050.300 5336163.566 536.378</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000026_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p11">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000026_p11_r0">
                      <gml:posList srsDimension="3">690035.100 5336162.400 518.726 690056.700 5336162.400 518.726 690056.700 5336162.400 533.726 690035.100 5336162.400 533.726 690035.100 5336162.400 518.726</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000026_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p12">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000026_p12_r0">
                      <gml:posList srsDimension="3">690056.700 5336162.400 518.726 690056.700 5336173.000 518.726 690056.700 5336173.000 533.726 690056.700 5336167.700 537.626 690056.700 5336162.400 533.726 690056.700 5336162.400 518.726</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000026_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p13">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000026_p13_r0">
                      <gml:posList srsDimension="3">690056.700 5336173.000 518.726 690035.100 5336173.000 518.726 690035.100 5336173.000 533.726 690056.700 5336173.000 533.726 690056.700 5336173.000 518.726</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000026_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p14">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000026_p14_r0">
                      <gml:posList srsDimension="3">690035.100 5336173.000 518.726 690035.100 5336162.400 518.726 690035.100 5336162.400 533.726 690035.100 5336167.700 537.626 690035.100 5336173.000 533.726 690035.100 5336173.000 518.726</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000026_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000026_p15">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690035.100 5336173.000 518.726 690056.700 5336173.000 518.726 690056.700 5336162.400 518.726 690035.100 5336162.400 518.726 690035.100 5336173.000 518.726</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000027">
      <gml:name>SC_B000027</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690081.900 5336131.000 518.691</gml:lowerCorner>
          <gml:upperCorner>690096.300 5336143.500 530.691</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>37</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>518.691</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1804</bldg:yearOfConstruction>
      <bldg:yearOfDemolition>1854</bldg:yearOfDemolition>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">12.000</bldg:measuredHeight>
      <bldg:storeysAboveGround>4</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000027_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000027_cs">
              <gml:surfaceMember xlink:href="#SC_B000027_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000027_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000027_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000027_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000027_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000027_p6"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000027_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000027_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690081.900 5336131.000 530.691 690096.300 5336131.000 530.691 690096.300 5336143.500 530.691 690081.900 5336143.500 530.691 690081.900 5336131.000 530.691</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000027_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000027_p2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000027_p2_r0">
                      <gml:posList srsDimension="3">690081.900 5336131.000 518.691 690096.300 5336131.000 518.691 690096.300 5336131.000 530.691 690081.900 5336131.000 530.691 690081.900 5336131.000 518.691</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000027_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000027_p3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000027_p3_r0">
                      <gml:posList srsDimension="3">690096.300 5336131.000 518.691 690096.300 5336143.500 518.691 690096.300 5336143.500 530.691 690096.300 5336131.000 530.691 690096.300 5336131.000 518.691</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000027_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000027_p4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000027_p4_r0">
                      <gml:posList srsDimension="3">690096.300 5336143.500 518.691 690081.900 5336143.500 518.691 690081.900 5336143.500 530.691 690096.300 5336143.500 530.691 690096.300 5336143.500 518.691</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000027_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000027_p5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="SC_B000027_p5_r0">
                      <gml:posList srsDimension="3">690081.900 5336143.500 518.691 690081.900 5336131.000 518.691 690081.900 5336131.000 530.691 690081.900 5336143.500 530.691 690081.900 5336143.500 518.691</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000027_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000027_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690081.900 5336143.500 518.691 690096.300 5336143.500 518.691 690096.300 5336131.000 518.691 690081.900 5336131.000 518.691 690081.900 5336143.500 518.691</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000028">
      <gml:name>SC_B000028</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690118.200 5336131.000 519.331</gml:lowerCorner>
          <gml:upperCorner>690132.400 5336144.800 539.231</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>38</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>519.331</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1852</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">19.900</bldg:measuredHeight>
      <bldg:storeysAboveGround>5</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000028_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000028_cs">
              <gml:surfaceMember xlink:href="#SC_B000028_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p11"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p12"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p13"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p14"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p15"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p16"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p17"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p18"/>
              <gml:surfaceMember xlink:href="#SC_B000028_p19"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000028_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690118.200 5336131.000 534.331 690132.400 5336131.000 534.331 690132.400 5336137.900 539.231 690118.200 5336137.900 539.231 690118.200 5336131.000 534.331</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690119.567 5336132.380 535.311 690119.567 5336135.830 537.761 690121.567 5336135.830 537.761 690121.567 5336132.380 535.311 690119.567 5336132.380 535.311</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690124.300 5336132.518 535.409 690124.300 5336135.692 537.663 690126.300 5336135.692 537.663 690126.300 5336132.518 535.409 690124.300 5336132.518 535.409</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690129.033 5336132.656 535.507 690129.033 5336135.554 537.565 690131.033 5336135.554 537.565 690131.033 5336132.656 535.507 690129.033 5336132.656 535.507</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000028_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690132.400 5336144.800 534.331 690118.200 5336144.800 534.331 690118.200 5336137.900 539.231 690132.400 5336137.900 539.231 690132.400 5336144.800 534.331</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000028_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690119.567 5336132.380 535.311 690121.567 5336132.380 535.311 690121.567 5336132.380 537.761 690119.567 5336132.380 537.761 690119.567 5336132.380 535.311</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690121.567 5336132.380 535.311 690121.567 5336135.830 537.761 690121.567 5336132.380 537.761 690121.567 5336132.380 535.311</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690119.567 5336132.380 535.311 690119.567 5336132.380 537.761 690119.567 5336135.830 537.761 690119.567 5336132.380 535.311</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000028_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690119.567 5336132.380 537.761 690121.567 5336132.380 537.761 690121.567 5336135.830 537.761 690119.567 5336135.830 537.761 690119.567 5336132.380 537.761</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000028_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690124.300 5336132.518 535.409 690126.300 5336132.518 535.409 690126.300 5336132.518 537.663 690124.300 5336132.518 537.663 690124.300 5336132.518 535.409</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690126.300 5336132.518 535.409 690126.300 5336135.692 537.663 690126.300 5336132.518 537.663 690126.300 5336132.518 535.409</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690124.300 5336132.518 535.409 690124.300 5336132.518 537.663 690124.300 5336135.692 537.663 690124.300 5336132.518 535.409</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000028_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690124.300 5336132.518 537.663 690126.300 5336132.518 537.663 690126.300 5336135.692 537.663 690124.300 5336135.692 537.663 690124.300 5336132.518 537.663</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000028_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690129.033 5336132.656 535.507 690131.033 5336132.656 535.507 690131.033 5336132.656 537.565 690129.033 5336132.656 537.565 690129.033 5336132.656 535.507</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p12">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690131.033 5336132.656 535.507 690131.033 5336135.554 537.565 690131.033 5336132.656 537.565 690131.033 5336132.656 535.507</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p13">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690129.033 5336132.656 535.507 690129.033 5336132.656 537.565 690129.033 5336135.554 537.565 690129.033 5336132.656 535.507</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000028_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p14">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690129.033 5336132.656 537.565 690131.033 5336132.656 537.565 690131.033 5336135.554 537.565 690129.033 5336135.554 537.565 690129.033 5336132.656 537.565</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000028_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p15">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690118.200 5336131.000 519.331 690132.400 5336131.000 519.331 690132.400 5336131.000 534.331 690118.200 5336131.000 534.331 690118.200 5336131.000 519.331</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000028_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p16">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690132.400 5336131.000 519.331 690132.400 5336144.800 519.331 690132.400 5336144.800 534.331 690132.400 5336137.900 539.231 690132.400 5336131.000 534.331 690132.400 5336131.000 519.331</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000028_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p17">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690132.400 5336144.800 519.331 690118.200 5336144.800 519.331 690118.200 5336144.800 534.331 690132.400 5336144.800 534.331 690132.400 5336144.800 519.331</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000028_s12">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p18">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690118.200 5336144.800 519.331 690118.200 5336131.000 519.331 690118.200 5336131.000 534.331 690118.200 5336137.900 539.231 690118.200 5336144.800 534.331 690118.200 5336144.800 519.331</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000028_s13">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000028_p19">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690118.200 5336144.800 519.331 690132.400 5336144.800 519.331 690132.400 5336131.000 519.331 690118.200 5336131.000 519.331 690118.200 5336144.800 519.331</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000029">
      <gml:name>SC_B000029</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690080.400 5336157.900 519.390</gml:lowerCorner>
          <gml:upperCorner>690100.900 5336173.000 529.690</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>39</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>519.390</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1749</bldg:yearOfConstruction>
      <bldg:yearOfDemolition>1961</bldg:yearOfDemolition>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">10.300</bldg:measuredHeight>
      <bldg:storeysAboveGround>2</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000029_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000029_cs">
              <gml:surfaceMember xlink:href="#SC_B000029_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000029_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000029_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000029_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000029_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000029_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000029_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000029_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000029_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000029_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000029_p11"/>
              <gml:surfaceMember xlink:href="#SC_B000029_p12"/>
              <gml:surfaceMember xlink:href="#SC_B000029_p13"/>
              <gml:surfaceMember xlink:href="#SC_B000029_p14"/>
              <gml:surfaceMember xlink:href="#SC_B000029_p15"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000029_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.400 5336157.900 525.390 690100.900 5336157.900 525.390 690100.900 5336165.450 529.690 690080.400 5336165.450 529.690 690080.400 5336157.900 525.390</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690084.525 5336159.410 526.250 690084.525 5336163.185 528.400 690086.525 5336163.185 528.400 690086.525 5336159.410 526.250 690084.525 5336159.410 526.250</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690094.775 5336159.561 526.336 690094.775 5336163.034 528.314 690096.775 5336163.034 528.314 690096.775 5336159.561 526.336 690094.775 5336159.561 526.336</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000029_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.900 5336173.000 525.390 690080.400 5336173.000 525.390 690080.400 5336165.450 529.690 690100.900 5336165.450 529.690 690100.900 5336173.000 525.390</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000029_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690084.525 5336159.410 526.250 690086.525 5336159.410 526.250 690086.525 5336159.410 528.400 690084.525 5336159.410 528.400 690084.525 5336159.410 526.250</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690086.525 5336159.410 526.250 690086.525 5336163.185 528.400 690086.525 5336159.410 528.400 690086.525 5336159.410 526.250</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690084.525 5336159.410 526.250 690084.525 5336159.410 528.400 690084.525 5336163.185 528.400 690084.525 5336159.410 526.250</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000029_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690084.525 5336159.410 528.400 690086.525 5336159.410 528.400 690086.525 5336163.185 528.400 690084.525 5336163.185 528.400 690084.525 5336159.410 528.400</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000029_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690094.775 5336159.561 526.336 690096.775 5336159.561 526.336 690096.775 5336159.561 528.314 690094.775 5336159.561 528.314 690094.775 5336159.561 526.336</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690096.775 5336159.561 526.336 690096.775 5336163.034 528.314 690096.775 5336159.561 528.314 690096.775 5336159.561 526.336</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690094.775 5336159.561 526.336 690094.775 5336159.561 528.314 690094.775 5336163.034 528.314 690094.775 5336159.561 526.336</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000029_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690094.775 5336159.561 528.314 690096.775 5336159.561 528.314 690096.775 5336163.034 528.314 690094.775 5336163.034 528.314 690094.775 5336159.561 528.314</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000029_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.400 5336157.900 519.390 690100.900 5336157.900 519.390 690100.900 5336157.900 525.390 690080.400 5336157.900 525.390 690080.400 5336157.900 519.390</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000029_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p12">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.900 5336157.900 519.390 690100.900 5336173.000 519.390 690100.900 5336173.000 525.390 690100.900 5336165.450 529.690 690100.900 5336157.900 525.390 690100.900 5336157.900 519.390</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000029_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p13">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690100.900 5336173.000 519.390 690080.400 5336173.000 519.390 690080.400 5336173.000 525.390 690100.900 5336173.000 525.390 690100.900 5336173.000 519.390</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000029_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p14">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.400 5336173.000 519.390 690080.400 5336157.900 519.390 690080.400 5336157.900 525.390 690080.400 5336165.450 529.690 690080.400 5336173.000 525.390 690080.400 5336173.000 519.390</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000029_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000029_p15">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690080.400 5336173.000 519.390 690100.900 5336173.000 519.390 690100.900 5336157.900 519.390 690080.400 5336157.900 519.390 690080.400 5336173.000 519.390</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="SC_B000030">
      <gml:name>SC_B000030</gml:name>
      <gml:boundedBy>
        <gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783" srsDimension="3">
          <gml:lowerCorner>690113.200 5336160.700 520.050</gml:lowerCorner>
          <gml:upperCorner>690128.100 5336173.000 532.950</gml:upperCorner>
        </gml:Envelope>
      </gml:boundedBy>
      <gen:intAttribute name="Parzelle">
        <gen:value>40</gen:value>
      </gen:intAttribute>
      <gen:doubleAttribute name="HoeheGrund">
        <gen:value>520.050</gen:value>
      </gen:doubleAttribute>
      <bldg:function>1000</bldg:function>
      <bldg:yearOfConstruction>1773</bldg:yearOfConstruction>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">12.900</bldg:measuredHeight>
      <bldg:storeysAboveGround>3</bldg:storeysAboveGround>
      <bldg:lod2Solid>
        <gml:Solid gml:id="SC_B000030_solid">
          <gml:exterior>
            <gml:CompositeSurface gml:id="SC_B000030_cs">
              <gml:surfaceMember xlink:href="#SC_B000030_p1"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p2"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p3"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p4"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p5"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p6"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p7"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p8"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p9"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p10"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p11"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p12"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p13"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p14"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p15"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p16"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p17"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p18"/>
              <gml:surfaceMember xlink:href="#SC_B000030_p19"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000030_s1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p1">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690113.200 5336160.700 529.050 690128.100 5336160.700 529.050 690128.100 5336166.850 532.950 690113.200 5336166.850 532.950 690113.200 5336160.700 529.050</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690114.683 5336161.930 529.830 690114.683 5336165.005 531.780 690116.683 5336165.005 531.780 690116.683 5336161.930 529.830 690114.683 5336161.930 529.830</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690119.650 5336162.053 529.908 690119.650 5336164.882 531.702 690121.650 5336164.882 531.702 690121.650 5336162.053 529.908 690119.650 5336162.053 529.908</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690124.617 5336162.176 529.986 690124.617 5336164.759 531.624 690126.617 5336164.759 531.624 690126.617 5336162.176 529.986 690124.617 5336162.176 529.986</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000030_s2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p2">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690128.100 5336173.000 529.050 690113.200 5336173.000 529.050 690113.200 5336166.850 532.950 690128.100 5336166.850 532.950 690128.100 5336173.000 529.050</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000030_s3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p3">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690114.683 5336161.930 529.830 690116.683 5336161.930 529.830 690116.683 5336161.930 531.780 690114.683 5336161.930 531.780 690114.683 5336161.930 529.830</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p4">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690116.683 5336161.930 529.830 690116.683 5336165.005 531.780 690116.683 5336161.930 531.780 690116.683 5336161.930 529.830</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p5">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690114.683 5336161.930 529.830 690114.683 5336161.930 531.780 690114.683 5336165.005 531.780 690114.683 5336161.930 529.830</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000030_s4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p6">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690114.683 5336161.930 531.780 690116.683 5336161.930 531.780 690116.683 5336165.005 531.780 690114.683 5336165.005 531.780 690114.683 5336161.930 531.780</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000030_s5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p7">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690119.650 5336162.053 529.908 690121.650 5336162.053 529.908 690121.650 5336162.053 531.702 690119.650 5336162.053 531.702 690119.650 5336162.053 529.908</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p8">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690121.650 5336162.053 529.908 690121.650 5336164.882 531.702 690121.650 5336162.053 531.702 690121.650 5336162.053 529.908</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p9">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690119.650 5336162.053 529.908 690119.650 5336162.053 531.702 690119.650 5336164.882 531.702 690119.650 5336162.053 529.908</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000030_s6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p10">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690119.650 5336162.053 531.702 690121.650 5336162.053 531.702 690121.650 5336164.882 531.702 690119.650 5336164.882 531.702 690119.650 5336162.053 531.702</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000030_s7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p11">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690124.617 5336162.176 529.986 690126.617 5336162.176 529.986 690126.617 5336162.176 531.624 690124.617 5336162.176 531.624 690124.617 5336162.176 529.986</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p12">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690126.617 5336162.176 529.986 690126.617 5336164.759 531.624 690126.617 5336162.176 531.624 690126.617 5336162.176 529.986</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p13">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690124.617 5336162.176 529.986 690124.617 5336162.176 531.624 690124.617 5336164.759 531.624 690124.617 5336162.176 529.986</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="SC_B000030_s8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p14">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690124.617 5336162.176 531.624 690126.617 5336162.176 531.624 690126.617 5336164.759 531.624 690124.617 5336164.759 531.624 690124.617 5336162.176 531.624</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000030_s9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p15">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690113.200 5336160.700 520.050 690128.100 5336160.700 520.050 690128.100 5336160.700 529.050 690113.200 5336160.700 529.050 690113.200 5336160.700 520.050</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000030_s10">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p16">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690128.100 5336160.700 520.050 690128.100 5336173.000 520.050 690128.100 5336173.000 529.050 690128.100 5336166.850 532.950 690128.100 5336160.700 529.050 690128.100 5336160.700 520.050</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000030_s11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p17">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690128.100 5336173.000 520.050 690113.200 5336173.000 520.050 690113.200 5336173.000 529.050 690128.100 5336173.000 529.050 690128.100 5336173.000 520.050</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="SC_B000030_s12">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p18">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690113.200 5336173.000 520.050 690113.200 5336160.700 520.050 690113.200 5336160.700 529.050 690113.200 5336166.850 532.950 690113.200 5336173.000 529.050 690113.200 5336173.000 520.050</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="SC_B000030_s13">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="SC_B000030_p19">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">690113.200 5336173.000 520.050 690128.100 5336173.000 520.050 690128.100 5336160.700 520.050 690113.200 5336160.700 520.050 690113.200 5336173.000 520.050</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <app:appearanceMember>
    <app:Appearance gml:id="SC_appearance">
      <app:theme>rgbTexture</app:theme>
      <app:surfaceDataMember>
        <app:X3DMaterial gml:id="SC_mat_roof_tiles">
          <app:diffuseColor>0.560 0.180 0.120</app:diffuseColor>
          <app:target>#SC_B000002_p1</app:target>
          <app:target>#SC_B000002_p2</app:target>
          <app:target>#SC_B000004_p1</app:target>
          <app:target>#SC_B000004_p2</app:target>
          <app:target>#SC_B000004_p6</app:target>
          <app:target>#SC_B000004_p10</app:target>
          <app:target>#SC_B000006_p1</app:target>
          <app:target>#SC_B000006_p2</app:target>
          <app:target>#SC_B000006_p3</app:target>
          <app:target>#SC_B000006_p4</app:target>
          <app:target>#SC_B000007_p1</app:target>
          <app:target>#SC_B000007_p2</app:target>
          <app:target>#SC_B000007_p6</app:target>
          <app:target>#SC_B000008_p1</app:target>
          <app:target>#SC_B000008_p2</app:target>
          <app:target>#SC_B000008_p6</app:target>
          <app:target>#SC_B000010_p1</app:target>
          <app:target>#SC_B000010_p2</app:target>
          <app:target>#SC_B000012_p1</app:target>
          <app:target>#SC_B000012_p2</app:target>
          <app:target>#SC_B000012_p6</app:target>
          <app:target>#SC_B000012_p10</app:target>
          <app:target>#SC_B000012_p14</app:target>
          <app:target>#SC_B000017_p1</app:target>
          <app:target>#SC_B000017_p2</app:target>
          <app:target>#SC_B000017_p6</app:target>
          <app:target>#SC_B000017_p10</app:target>
          <app:target>#SC_B000018_p1</app:target>
          <app:target>#SC_B000018_p2</app:target>
          <app:target>#SC_B000018_p6</app:target>
          <app:target>#SC_B000019_p1</app:target>
          <app:target>#SC_B000019_p2</app:target>
          <app:target>#SC_B000019_p6</app:target>
          <app:target>#SC_B000020_p1</app:target>
          <app:target>#SC_B000020_p2</app:target>
          <app:target>#SC_B000020_p6</app:target>
          <app:target>#SC_B000020_p10</app:target>
          <app:target>#SC_B000020_p14</app:target>
          <app:target>#SC_B000024_p1</app:target>
          <app:target>#SC_B000024_p2</app:target>
          <app:target>#SC_B000024_p6</app:target>
          <app:target>#SC_B000024_p10</app:target>
          <app:target>#SC_B000024_p14</app:target>
          <app:target>#SC_B000025_p1</app:target>
          <app:target>#SC_B000025_p2</app:target>
          <app:target>#SC_B000025_p6</app:target>
          <app:target>#SC_B000025_p10</app:target>
          <app:target>#SC_B000026_p1</app:target>
          <app:target>#SC_B000026_p2</app:target>
          <app:target>#SC_B000026_p6</app:target>
          <app:target>#SC_B000026_p10</app:target>
          <app:target>#SC_B000028_p1</app:target>
          <app:target>#SC_B000028_p2</app:target>
          <app:target>#SC_B000028_p6</app:target>
          <app:target>#SC_B000028_p10</app:target>
          <app:target>#SC_B000028_p14</app:target>
          <app:target>#SC_B000029_p1</app:target>
          <app:target>#SC_B000029_p2</app:target>
          <app:target>#SC_B000029_p6</app:target>
          <app:target>#SC_B000029_p10</app:target>
        </app:X3DMaterial>
      </app:surfaceDataMember>
      <app:surfaceDataMember>
        <app:X3DMaterial gml:id="SC_mat_roof_slate">
          <app:diffuseColor>0.220 0.230 0.260</app:diffuseColor>
          <app:target>#SC_B000002_part1_p1</app:target>
          <app:target>#SC_B000005_p1</app:target>
          <app:target>#SC_B000005_p2</app:target>
          <app:target>#SC_B000005_p6</app:target>
          <app:target>#SC_B000005_p10</app:target>
          <app:target>#SC_B000007_part1_p1</app:target>
          <app:target>#SC_B000009_p1</app:target>
          <app:target>#SC_B000009_p2</app:target>
          <app:target>#SC_B000009_p3</app:target>
          <app:target>#SC_B000009_p4</app:target>
          <app:target>#SC_B000013_p1</app:target>
          <app:target>#SC_B000013_p2</app:target>
          <app:target>#SC_B000013_p6</app:target>
          <app:target>#SC_B000013_p10</app:target>
          <app:target>#SC_B000013_p14</app:target>
          <app:target>#SC_B000014_p1</app:target>
          <app:target>#SC_B000014_p2</app:target>
          <app:target>#SC_B000014_p6</app:target>
          <app:target>#SC_B000014_p10</app:target>
          <app:target>#SC_B000014_p14</app:target>
          <app:target>#SC_B000014_part1_p1</app:target>
          <app:target>#SC_B000015_p1</app:target>
          <app:target>#SC_B000015_p2</app:target>
          <app:target>#SC_B000015_p6</app:target>
          <app:target>#SC_B000015_p10</app:target>
          <app:target>#SC_B000015_p14</app:target>
          <app:target>#SC_B000024_part1_p1</app:target>
          <app:target>#SC_B000030_p1</app:target>
          <app:target>#SC_B000030_p2</app:target>
          <app:target>#SC_B000030_p6</app:target>
          <app:target>#SC_B000030_p10</app:target>
          <app:target>#SC_B000030_p14</app:target>
        </app:X3DMaterial>
      </app:surfaceDataMember>
      <app:surfaceDataMember>
        <app:X3DMaterial gml:id="SC_mat_roof_flat">
          <app:diffuseColor>0.450 0.440 0.420</app:diffuseColor>
          <app:target>#SC_B000001_p1</app:target>
          <app:target>#SC_B000003_p1</app:target>
          <app:target>#SC_B000011_p1</app:target>
          <app:target>#SC_B000016_p1</app:target>
          <app:target>#SC_B000021_p1</app:target>
          <app:target>#SC_B000022_p1</app:target>
          <app:target>#SC_B000022_p2</app:target>
          <app:target>#SC_B000023_p1</app:target>
          <app:target>#SC_B000027_p1</app:target>
        </app:X3DMaterial>
      </app:surfaceDataMember>
      <app:surfaceDataMember>
        <app:X3DMaterial gml:id="SC_mat_wall_plaster">
          <app:diffuseColor>0.850 0.780 0.640</app:diffuseColor>
          <app:target>#SC_B000001_p2</app:target>
          <app:target>#SC_B000001_p3</app:target>
          <app:target>#SC_B000001_p4</app:target>
          <app:target>#SC_B000001_p5</app:target>
          <app:target>#SC_B000001_p6</app:target>
          <app:target>#SC_B000001_p7</app:target>
          <app:target>#SC_B000001_p8</app:target>
          <app:target>#SC_B000001_p9</app:target>
          <app:target>#SC_B000003_p2</app:target>
          <app:target>#SC_B000003_p3</app:target>
          <app:target>#SC_B000003_p4</app:target>
          <app:target>#SC_B000003_p5</app:target>
          <app:target>#SC_B000004_p3</app:target>
          <app:target>#SC_B000004_p4</app:target>
          <app:target>#SC_B000004_p5</app:target>
          <app:target>#SC_B000004_p7</app:target>
          <app:target>#SC_B000004_p8</app:target>
          <app:target>#SC_B000004_p9</app:target>
          <app:target>#SC_B000004_p11</app:target>
          <app:target>#SC_B000004_p12</app:target>
          <app:target>#SC_B000004_p13</app:target>
          <app:target>#SC_B000004_p14</app:target>
          <app:target>#SC_B000005_p3</app:target>
          <app:target>#SC_B000005_p4</app:target>
          <app:target>#SC_B000005_p5</app:target>
          <app:target>#SC_B000005_p7</app:target>
          <app:target>#SC_B000005_p8</app:target>
          <app:target>#SC_B000005_p9</app:target>
          <app:target>#SC_B000005_p11</app:target>
          <app:target>#SC_B000005_p12</app:target>
          <app:target>#SC_B000005_p13</app:target>
          <app:target>#SC_B000005_p14</app:target>
          <app:target>#SC_B000006_p5</app:target>
          <app:target>#SC_B000006_p6</app:target>
          <app:target>#SC_B000006_p7</app:target>
          <app:target>#SC_B000006_p8</app:target>
          <app:target>#SC_B000007_p3</app:target>
          <app:target>#SC_B000007_p4</app:target>
          <app:target>#SC_B000007_p5</app:target>
          <app:target>#SC_B000007_p7</app:target>
          <app:target>#SC_B000007_p8</app:target>
          <app:target>#SC_B000007_p9</app:target>
          <app:target>#SC_B000007_p10</app:target>
          <app:target>#SC_B000008_p3</app:target>
          <app:target>#SC_B000008_p4</app:target>
          <app:target>#SC_B000008_p5</app:target>
          <app:target>#SC_B000008_p7</app:target>
          <app:target>#SC_B000008_p8</app:target>
          <app:target>#SC_B000008_p9</app:target>
          <app:target>#SC_B000008_p10</app:target>
          <app:target>#SC_B000009_p5</app:target>
          <app:target>#SC_B000009_p6</app:target>
          <app:target>#SC_B000009_p7</app:target>
          <app:target>#SC_B000009_p8</app:target>
          <app:target>#SC_B000010_p3</app:target>
          <app:target>#SC_B000010_p4</app:target>
          <app:target>#SC_B000010_p5</app:target>
          <app:target>#SC_B000010_p6</app:target>
          <app:target>#SC_B000012_p3</app:target>
          <app:target>#SC_B000012_p4</app:target>
          <app:target>#SC_B000012_p5</app:target>
          <app:target>#SC_B000012_p7</app:target>
          <app:target>#SC_B000012_p8</app:target>
          <app:target>#SC_B000012_p9</app:target>
          <app:target>#SC_B000012_p11</app:target>
          <app:target>#SC_B000012_p12</app:target>
          <app:target>#SC_B000012_p13</app:target>
          <app:target>#SC_B000012_p15</app:target>
          <app:target>#SC_B000012_p16</app:target>
          <app:target>#SC_B000012_p17</app:target>
          <app:target>#SC_B000012_p18</app:target>
          <app:target>#SC_B000013_p3</app:target>
          <app:target>#SC_B000013_p4</app:target>
          <app:target>#SC_B000013_p5</app:target>
          <app:target>#SC_B000013_p7</app:target>
          <app:target>#SC_B000013_p8</app:target>
          <app:target>#SC_B000013_p9</app:target>
          <app:target>#SC_B000013_p11</app:target>
          <app:target>#SC_B000013_p12</app:target>
          <app:target>#SC_B000013_p13</app:target>
          <app:target>#SC_B000013_p15</app:target>
          <app:target>#SC_B000013_p16</app:target>
          <app:target>#SC_B000013_p17</app:target>
          <app:target>#SC_B000013_p18</app:target>
          <app:target>#SC_B000014_p3</app:target>
          <app:target>#SC_B000014_p4</app:target>
          <app:target>#SC_B000014_p5</app:target>
          <app:target>#SC_B000014_p7</app:target>
          <app:target>#SC_B000014_p8</app:target>
          <app:target>#SC_B000014_p9</app:target>
          <app:target>#SC_B000014_p11</app:target>
          <app:target>#SC_B000014_p12</app:target>
          <app:target>#SC_B000014_p13</app:target>
          <app:target>#SC_B000015_p3</app:target>
          <app:target>#SC_B000015_p4</app:target>
          <app:target>#SC_B000015_p5</app:target>
          <app:target>#SC_B000015_p7</app:target>
          <app:target>#SC_B000015_p8</app:target>
          <app:target>#SC_B000015_p9</app:target>
          <app:target>#SC_B000015_p11</app:target>
          <app:target>#SC_B000015_p12</app:target>
          <app:target>#SC_B000015_p13</app:target>
          <app:target>#SC_B000015_p15</app:target>
          <app:target>#SC_B000015_p16</app:target>
          <app:target>#SC_B000015_p17</app:target>
          <app:target>#SC_B000015_p18</app:target>
          <app:target>#SC_B000017_p3</app:target>
          <app:target>#SC_B000017_p4</app:target>
          <app:target>#SC_B000017_p5</app:target>
          <app:target>#SC_B000017_p7</app:target>
          <app:target>#SC_B000017_p8</app:target>
          <app:target>#SC_B000017_p9</app:target>
          <app:target>#SC_B000017_p11</app:target>
          <app:target>#SC_B000017_p12</app:target>
          <app:target>#SC_B000017_p13</app:target>
          <app:target>#SC_B000017_p14</app:target>
          <app:target>#SC_B000018_p3</app:target>
          <app:target>#SC_B000018_p4</app:target>
          <app:target>#SC_B000018_p5</app:target>
          <app:target>#SC_B000018_p7</app:target>
          <app:target>#SC_B000018_p8</app:target>
          <app:target>#SC_B000018_p9</app:target>
          <app:target>#SC_B000018_p10</app:target>
          <app:target>#SC_B000019_p3</app:target>
          <app:target>#SC_B000019_p4</app:target>
          <app:target>#SC_B000019_p5</app:target>
          <app:target>#SC_B000019_p7</app:target>
          <app:target>#SC_B000019_p8</app:target>
          <app:target>#SC_B000019_p9</app:target>
          <app:target>#SC_B000019_p10</app:target>
          <app:target>#SC_B000020_p3</app:target>
          <app:target>#SC_B000020_p4</app:target>
          <app:target>#SC_B000020_p5</app:target>
          <app:target>#SC_B000020_p7</app:target>
          <app:target>#SC_B000020_p8</app:target>
          <app:target>#SC_B000020_p9</app:target>
          <app:target>#SC_B000020_p11</app:target>
          <app:target>#SC_B000020_p12</app:target>
          <app:target>#SC_B000020_p13</app:target>
          <app:target>#SC_B000020_p15</app:target>
          <app:target>#SC_B000020_p16</app:target>
          <app:target>#SC_B000020_p17</app:target>
          <app:target>#SC_B000020_p18</app:target>
          <app:target>#SC_B000021_p2</app:target>
          <app:target>#SC_B000021_p3</app:target>
          <app:target>#SC_B000021_p4</app:target>
          <app:target>#SC_B000021_p5</app:target>
          <app:target>#SC_B000022_p3</app:target>
          <app:target>#SC_B000022_p4</app:target>
          <app:target>#SC_B000022_p5</app:target>
          <app:target>#SC_B000022_p6</app:target>
          <app:target>#SC_B000022_p7</app:target>
          <app:target>#SC_B000022_p8</app:target>
          <app:target>#SC_B000022_p9</app:target>
          <app:target>#SC_B000022_p10</app:target>
          <app:target>#SC_B000024_p3</app:target>
          <app:target>#SC_B000024_p4</app:target>
          <app:target>#SC_B000024_p5</app:target>
          <app:target>#SC_B000024_p7</app:target>
          <app:target>#SC_B000024_p8</app:target>
          <app:target>#SC_B000024_p9</app:target>
          <app:target>#SC_B000024_p11</app:target>
          <app:target>#SC_B000024_p12</app:target>
          <app:target>#SC_B000024_p13</app:target>
          <app:target>#SC_B000024_p15</app:target>
          <app:target>#SC_B000024_p16</app:target>
          <app:target>#SC_B000024_p17</app:target>
          <app:target>#SC_B000024_p18</app:target>
          <app:target>#SC_B000026_p3</app:target>
          <app:target>#SC_B000026_p4</app:target>
          <app:target>#SC_B000026_p5</app:target>
          <app:target>#SC_B000026_p7</app:target>
          <app:target>#SC_B000026_p8</app:target>
          <app:target>#SC_B000026_p9</app:target>
          <app:target>#SC_B000028_p3</app:target>
          <app:target>#SC_B000028_p4</app:target>
          <app:target>#SC_B000028_p5</app:target>
          <app:target>#SC_B000028_p7</app:target>
          <app:target>#SC_B000028_p8</app:target>
          <app:target>#SC_B000028_p9</app:target>
          <app:target>#SC_B000028_p11</app:target>
          <app:target>#SC_B000028_p12</app:target>
          <app:target>#SC_B000028_p13</app:target>
          <app:target>#SC_B000028_p15</app:target>
          <app:target>#SC_B000028_p16</app:target>
          <app:target>#SC_B000028_p17</app:target>
          <app:target>#SC_B000028_p18</app:target>
          <app:target>#SC_B000030_p3</app:target>
          <app:target>#SC_B000030_p4</app:target>
          <app:target>#SC_B000030_p5</app:target>
          <app:target>#SC_B000030_p7</app:target>
          <app:target>#SC_B000030_p8</app:target>
          <app:target>#SC_B000030_p9</app:target>
          <app:target>#SC_B000030_p11</app:target>
          <app:target>#SC_B000030_p12</app:target>
          <app:target>#SC_B000030_p13</app:target>
          <app:target>#SC_B000030_p15</app:target>
          <app:target>#SC_B000030_p16</app:target>
          <app:target>#SC_B000030_p17</app:target>
          <app:target>#SC_B000030_p18</app:target>
        </app:X3DMaterial>
      </app:surfaceDataMember>
      <app:surfaceDataMember>
        <app:X3DMaterial gml:id="SC_mat_wall_brick">
          <app:diffuseColor>0.580 0.300 0.220</app:diffuseColor>
          <app:target>#SC_B000002_part1_p2</app:target>
          <app:target>#SC_B000002_part1_p3</app:target>
          <app:target>#SC_B000002_part1_p4</app:target>
          <app:target>#SC_B000002_part1_p5</app:target>
          <app:target>#SC_B000007_part1_p2</app:target>
          <app:target>#SC_B000007_part1_p3</app:target>
          <app:target>#SC_B000007_part1_p4</app:target>
          <app:target>#SC_B000007_part1_p5</app:target>
          <app:target>#SC_B000011_p2</app:target>
          <app:target>#SC_B000011_p3</app:target>
          <app:target>#SC_B000011_p4</app:target>
          <app:target>#SC_B000011_p5</app:target>
          <app:target>#SC_B000014_part1_p2</app:target>
          <app:target>#SC_B000014_part1_p3</app:target>
          <app:target>#SC_B000014_part1_p4</app:target>
          <app:target>#SC_B000014_part1_p5</app:target>
          <app:target>#SC_B000016_p2</app:target>
          <app:target>#SC_B000016_p3</app:target>
          <app:target>#SC_B000016_p4</app:target>
          <app:target>#SC_B000016_p5</app:target>
          <app:target>#SC_B000024_part1_p2</app:target>
          <app:target>#SC_B000024_part1_p3</app:target>
          <app:target>#SC_B000024_part1_p4</app:target>
          <app:target>#SC_B000024_part1_p5</app:target>
          <app:target>#SC_B000025_p3</app:target>
          <app:target>#SC_B000025_p4</app:target>
          <app:target>#SC_B000025_p5</app:target>
          <app:target>#SC_B000025_p7</app:target>
          <app:target>#SC_B000025_p8</app:target>
          <app:target>#SC_B000025_p9</app:target>
          <app:target>#SC_B000025_p11</app:target>
          <app:target>#SC_B000025_p12</app:target>
          <app:target>#SC_B000025_p13</app:target>
          <app:target>#SC_B000025_p14</app:target>
          <app:target>#SC_B000029_p3</app:target>
          <app:target>#SC_B000029_p4</app:target>
          <app:target>#SC_B000029_p5</app:target>
          <app:target>#SC_B000029_p7</app:target>
          <app:target>#SC_B000029_p8</app:target>
          <app:target>#SC_B000029_p9</app:target>
          <app:target>#SC_B000029_p11</app:target>
          <app:target>#SC_B000029_p12</app:target>
          <app:target>#SC_B000029_p13</app:target>
          <app:target>#SC_B000029_p14</app:target>
        </app:X3DMaterial>
      </app:surfaceDataMember>
      <app:surfaceDataMember>
        <app:ParameterizedTexture gml:id="SC_tex_facade">
          <app:imageURI>sample_city_facade.png</app:imageURI>
          <app:mimeType>image/png</app:mimeType>
          <app:wrapMode>wrap</app:wrapMode>
          <app:target uri="#SC_B000002_p3">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000002_p3_r0">0.0000 0.0000 2.2500 0.0000 2.2500 1.5000 0.0000 1.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000002_p4">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000002_p4_r0">0.0000 0.0000 2.0333 0.0000 2.0333 1.5000 1.0167 2.4333 0.0000 1.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000002_p5">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000002_p5_r0">0.0000 0.0000 2.2500 0.0000 2.2500 1.5000 0.0000 1.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000002_p6">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000002_p6_r0">0.0000 0.0000 2.0333 0.0000 2.0333 1.5000 1.0167 2.4333 0.0000 1.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000014_p15">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000014_p15_r0">0.0000 0.0000 2.0333 0.0000 2.0333 2.5000 0.0000 2.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000014_p16">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000014_p16_r0">0.0000 0.0000 2.0167 0.0000 2.0167 2.5000 1.0083 3.2333 0.0000 2.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000014_p17">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000014_p17_r0">0.0000 0.0000 2.0333 0.0000 2.0333 2.5000 0.0000 2.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000014_p18">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000014_p18_r0">0.0000 0.0000 2.0167 0.0000 2.0167 2.5000 1.0083 3.2333 0.0000 2.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000023_p2">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000023_p2_r0">0.0000 0.0000 2.8000 0.0000 2.8000 1.5000 0.0000 1.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000023_p3">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000023_p3_r0">0.0000 0.0000 2.3167 0.0000 2.3167 1.5000 0.0000 1.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000023_p4">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000023_p4_r0">0.0000 0.0000 2.8000 0.0000 2.8000 1.5000 0.0000 1.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000023_p5">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000023_p5_r0">0.0000 0.0000 2.3167 0.0000 2.3167 1.5000 0.0000 1.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000026_p11">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000026_p11_r0">0.0000 0.0000 3.6000 0.0000 3.6000 2.5000 0.0000 2.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000026_p12">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000026_p12_r0">0.0000 0.0000 1.7667 0.0000 1.7667 2.5000 0.8833 3.1500 0.0000 2.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000026_p13">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000026_p13_r0">0.0000 0.0000 3.6000 0.0000 3.6000 2.5000 0.0000 2.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000026_p14">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000026_p14_r0">0.0000 0.0000 1.7667 0.0000 1.7667 2.5000 0.8833 3.1500 0.0000 2.5000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000027_p2">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000027_p2_r0">0.0000 0.0000 2.4000 0.0000 2.4000 2.0000 0.0000 2.0000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000027_p3">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000027_p3_r0">0.0000 0.0000 2.0833 0.0000 2.0833 2.0000 0.0000 2.0000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000027_p4">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000027_p4_r0">0.0000 0.0000 2.4000 0.0000 2.4000 2.0000 0.0000 2.0000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
          <app:target uri="#SC_B000027_p5">
            <app:TexCoordList>
              <app:textureCoordinates ring="#SC_B000027_p5_r0">0.0000 0.0000 2.0833 0.0000 2.0833 2.0000 0.0000 2.0000 0.0000 0.0000</app:textureCoordinates>
            </app:TexCoordList>
          </app:target>
        </app:ParameterizedTexture>
      </app:surfaceDataMember>
    </app:Appearance>
  </app:appearanceMember>
</CityModel>
