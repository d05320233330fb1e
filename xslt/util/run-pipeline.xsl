<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/util/run-pipeline.xsl - run a robomda pipeline manifest in pure XSLT.

  Reads:   a pipeline manifest (urn:robomda:pipeline:1, pipelines/*.xml) as
           the source document.
  Writes:  for a pipeline that yields files: the files, through
           write-files.xsl (paths relative to the base output URI), and as
           the principal result an fs:written list of them; for one that
           yields a model: that model, byte for byte as the driver's.
  Params:  model                  absolute URI of the XMI file
                                  (file:///...); required.
           model-dir-from-output  the XMI file's folder relative to the
                                  output folder ("." by default).
           package-name           package name ("" = derived from the model).
           type-map               ROS targets: URI of a user type map.
           model-path             folder URIs (space-separated) that model
                                  files the model references may be read
                                  from besides its own folder.
           features, feature-model, resolution
                                  URIs of a FeatureIDE configuration, its
                                  feature model and the resolution model:
                                  the configure step runs (step/@if) only
                                  when features is given, or when the
                                  model has jobs given as configurations
                                  (step/@if job-configurations; the
                                  step's model-uri param is $model).
  Errors:  RUN001 no model given; any error of a step's stylesheet
           (fn:transform passes it on unchanged).

  Uses fn:transform (XSLT 3.0, available in Saxon-HE 10+, SaxonC-HE and
  Saxon-HE Java). The driver does the same in Python and also validates each
  stage against its XSD, which this runner leaves to the caller (XSD
  validation needs a schema-aware processor in pure XSLT).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:p="urn:robomda:pipeline:1"
    xmlns:fs="urn:robomda:fileset:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:import href="write-files.xsl"/>
  <xsl:include href="../common/errors.xsl"/>
  <xsl:include href="../common/indent.xsl"/>

  <!-- a model is serialized as the chain's own steps serialize it -->
  <xsl:output method="xml" indent="no" encoding="UTF-8"/>

  <xsl:param name="model" as="xs:string" select="''">
    <!-- URI of the XMI model to transform -->
  </xsl:param>
  <xsl:param name="model-dir-from-output" as="xs:string" select="'.'">
    <!-- the model's folder relative to the output folder -->
  </xsl:param>
  <xsl:param name="package-name" as="xs:string" select="''">
    <!-- package name; empty = derived from the model name -->
  </xsl:param>
  <xsl:param name="type-map" as="xs:string" select="''">
    <!-- ROS targets: absolute URI of a user type map; empty = none -->
  </xsl:param>
  <xsl:param name="model-path" as="xs:string" select="''">
    <!-- folder URIs, space-separated: where referenced model files may be -->
  </xsl:param>

  <xsl:param name="features" as="xs:string" select="''">
    <!-- URI of a FeatureIDE configuration: runs the configure step ("" = none) -->
  </xsl:param>
  <xsl:param name="feature-model" as="xs:string" select="''">
    <!-- URI of the configuration's FeatureIDE feature model -->
  </xsl:param>
  <xsl:param name="resolution" as="xs:string" select="''">
    <!-- URI of the resolution model (docs/variability.md) -->
  </xsl:param>
  <xsl:param name="package-version" as="xs:string" select="''">
    <!-- the package's version; empty = 0.0.0 -->
  </xsl:param>
  <xsl:param name="maintainer-name" as="xs:string" select="''">
    <!-- the package maintainer's name; empty = a placeholder -->
  </xsl:param>
  <xsl:param name="maintainer-email" as="xs:string" select="''">
    <!-- the package maintainer's e-mail address; empty = a placeholder -->
  </xsl:param>
  <xsl:param name="license" as="xs:string" select="''">
    <!-- the package's license; empty = TODO -->
  </xsl:param>
  <xsl:param name="copyright-year" as="xs:string" select="''">
    <!-- the year of the copyright notices; empty = notices without a year -->
  </xsl:param>

  <xsl:global-context-item as="document-node(element(p:pipeline))"/>

  <!-- Every step of a manifest, includes expanded, with absolute URIs. -->
  <xsl:function name="fp:steps" as="element(p:step)*">
    <xsl:param name="manifest" as="element(p:pipeline)"/>
    <xsl:for-each select="$manifest/(p:include | p:step)">
      <xsl:choose>
        <xsl:when test="self::p:include">
          <xsl:sequence select="fp:steps(doc(resolve-uri(@href, base-uri(.)))/p:pipeline)"/>
        </xsl:when>
        <xsl:otherwise>
          <p:step name="{@name}" stylesheet="{resolve-uri(@stylesheet, base-uri(.))}">
            <xsl:copy-of select="@if"/>
            <xsl:copy-of select="p:param"/>
          </p:step>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:param-value" as="xs:string">
    <xsl:param name="param" as="element(p:param)"/>
    <xsl:sequence select="
      if ($param/@value) then string($param/@value)
      else if ($param/@from = 'model-file-name') then tokenize($model, '/')[last()]
      else if ($param/@from = 'model-dir-from-output') then $model-dir-from-output
      else if ($param/@from = 'package-name') then $package-name
      else if ($param/@from = 'type-map') then $type-map
      else if ($param/@from = 'package-version') then $package-version
      else if ($param/@from = 'maintainer-name') then $maintainer-name
      else if ($param/@from = 'maintainer-email') then $maintainer-email
      else if ($param/@from = 'license') then $license
      else if ($param/@from = 'copyright-year') then $copyright-year
      else if ($param/@from = 'model-path') then $model-path
      else if ($param/@from = 'features') then $features
      else if ($param/@from = 'feature-model') then $feature-model
      else if ($param/@from = 'resolution') then $resolution
      else if ($param/@from = 'model-uri') then $model
      else ''"/>
  </xsl:function>

  <!-- Run the steps from position $at on $input. -->
  <xsl:function name="fp:run" as="document-node()">
    <xsl:param name="steps" as="element(p:step)*"/>
    <xsl:param name="input" as="document-node()"/>
    <xsl:choose>
      <xsl:when test="empty($steps)">
        <xsl:sequence select="$input"/>
      </xsl:when>
      <xsl:when test="exists(head($steps)/@if) and not(some $v in tokenize(head($steps)/@if) satisfies
                      ($v eq 'features' and $features ne '' or $v eq 'job-configurations' and exists(
                       $input/*:model/*:coordination/*:job/*:stereotype[@name eq 'Job']/*:tag[@name eq 'configuration'][normalize-space(@value)])))">
        <!-- a step for a configuration, and neither the runner nor the model gives one -->
        <xsl:sequence select="fp:run(tail($steps), $input)"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:variable name="step" as="element(p:step)" select="head($steps)"/>
        <xsl:variable name="params" as="map(xs:QName, item()*)" select="map:merge(
            for $param in $step/p:param
            return map:entry(QName('', $param/@name), xs:untypedAtomic(fp:param-value($param))))"
            xmlns:map="http://www.w3.org/2005/xpath-functions/map"/>
        <xsl:variable name="result" as="map(*)" select="transform(map{
            'stylesheet-location': string($step/@stylesheet),
            'source-node': $input,
            'stylesheet-params': $params})"/>
        <xsl:sequence select="fp:run(tail($steps), $result?output)"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <xsl:template match="/" as="item()*">
    <xsl:if test="$model = ''">
      <xsl:sequence select="f:fail('RUN001', (), 'run-pipeline.xsl needs the parameter model (URI of the XMI file)')"/>
    </xsl:if>
    <xsl:variable name="model-doc" as="document-node()" select="doc(resolve-uri($model, static-base-uri()))"/>
    <xsl:variable name="last" as="document-node()" select="fp:run(fp:steps(p:pipeline), $model-doc)"/>
    <xsl:choose>
      <xsl:when test="p:pipeline/@yields = 'files'">
        <xsl:apply-templates select="$last" mode="m:write-files" xmlns:m="urn:robomda:xslt:mode"/>
        <xsl:variable name="listing" as="document-node()">
          <xsl:document>
            <fs:written xmlns:fs="urn:robomda:fileset:1">
              <xsl:for-each select="$last/fs:files/fs:file">
                <fs:file path="{f:written-path(.)}"/>
              </xsl:for-each>
            </fs:written>
          </xsl:document>
        </xsl:variable>
        <xsl:sequence select="f:indent($listing)"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:sequence select="$last"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:template>
</xsl:stylesheet>
